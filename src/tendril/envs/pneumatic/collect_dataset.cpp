#include "tendril/envs/pneumatic/collect_dataset.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/envs/pneumatic/decimal_text.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::pneumatic {

PneumaticDataset record_pneumatic_dataset(Env& robot, SaturatingSignal& signal, int rows,
                                          double period, uint64_t seed) {
  require(rows >= 1, "record at least one row", "record_pneumatic_dataset");
  const int observed = robot.observation_space().size();
  require(robot.action_space().size() == 9 && (observed == 9 || observed == 18),
          "the robot must take 9 pressures and observe 9 tip coordinates (and 9 pressures)",
          "record_pneumatic_dataset");
  PneumaticDataset data;
  data.time_s.resize(rows);
  data.commands_bar.resize(rows, 9);
  data.tips_mm.resize(rows, 9);
  if (observed == 18) data.pressures_bar.resize(rows, 9);

  // Values are kept at the resolution that matters (1 µm, 0.1 mbar), so the file stays short;
  // the commands are rounded before they are sent, so the file holds what was sent (to the
  // float precision of the interface).
  Observation observation = robot.reset(seed);
  for (int k = 0; k < rows; ++k) {
    data.time_s[k] = rounded(k * period, 1e9);
    for (int c = 0; c < 9; ++c) {
      data.tips_mm(k, c) = rounded(observation[c], 1e3);
      if (observed == 18) data.pressures_bar(k, c) = rounded(observation[9 + c], 1e4);
    }
    physics::pneumatic::ChamberVector commands = signal.next(period);
    for (int c = 0; c < 9; ++c) commands[c] = rounded(commands[c], 1e4);
    data.commands_bar.row(k) = commands.transpose();
    if (k + 1 == rows) break;
    const Step step = robot.step(commands.cast<float>());
    if (step.terminated || step.truncated) {
      throw Error("the robot ended the recording at t = " + std::to_string(data.time_s[k]) +
                      " s (" + (step.terminated ? "terminated" : "truncated") + ")",
                  "record_pneumatic_dataset");
    }
    observation = step.observation;
  }
  return data;
}

CollectionReport collect_pneumatic_dataset(const Config& config,
                                           const std::filesystem::path& output,
                                           const std::string& invocation) {
  const Config robot_config = config.child("robot");
  const std::string id = robot_config.get_or<std::string>("id", "PneumaticArm/Robot-v0");
  Config params = robot_config.child("params");
  const double period = params.get_or<double>("control_period_s", 0.1);
  const double duration = config.get_or<double>("duration_s", 600.0);
  if (!(std::isfinite(duration) && duration > 0.0)) {
    throw Error("must be positive", key_where(config, "duration_s"));
  }
  if (!(std::isfinite(period) && period > 0.0)) {
    throw Error("must be positive", key_where(params, "control_period_s"));
  }
  const int rows = static_cast<int>(std::lround(duration / period));
  const uint64_t seed = config.get_or<uint64_t>("seed", 0);
  const SaturatingSignalSpec signal_spec = saturating_signal_from(config.child("signal"));
  const std::string configured = config.get_or<std::string>("output", "");
  const std::filesystem::path file = output.empty() ? std::filesystem::path(configured) : output;
  if (file.empty()) throw Error("no output file: set `output` or pass --out", config.source());
  if (std::filesystem::exists(file)) {
    throw Error("the data set file exists; nothing was overwritten", file.string());
  }

  if (!params.has("observe_pressures")) params.set("observe_pressures", "true");
  if (!params.has("max_episode_steps")) params.set("max_episode_steps", std::to_string(rows + 1));
  const std::unique_ptr<Env> robot = make(id, params);  // rejects unknown robot parameters
  config.reject_unknown();
  require(robot->action_space().high().maxCoeff() >= signal_spec.ceiling_max - 1e-6,
          "the signal's ceiling_max_bar exceeds the robot's pressure range",
          config.source() + ": signal.ceiling_max_bar");

  SaturatingSignal signal(signal_spec, Rng(seed, 0x5a7u));
  const auto start = std::chrono::steady_clock::now();
  CollectionReport report;
  report.data = record_pneumatic_dataset(*robot, signal, rows, period, seed);
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  auto& meta = report.data.metadata;
  meta.emplace_back("protocol", "seed 002 Sec. III-C: dynamically saturating pressure signal");
  meta.emplace_back("command", invocation);
  meta.emplace_back("robot", id);
  meta.emplace_back("rows", std::to_string(rows));
  // What the regulators accept: a reader refuses a command beyond it (a damaged file).
  meta.emplace_back("command_ceiling_bar",
                    shortest_text(static_cast<double>(robot->action_space().high().maxCoeff())));
  std::ostringstream period_text;
  period_text << period;
  meta.emplace_back("period_s", period_text.str());
  meta.emplace_back("resolution", "tips 0.001 mm, pressures and commands 0.0001 bar");
  meta.emplace_back("row_convention",
                    "tips and pressures measured at time_s; commands sent at time_s and held "
                    "until the next row");
  meta.emplace_back("frame", "robot frame, origin on the base plane, z negative downward");
  std::istringstream resolved(config.dump());
  for (std::string line; std::getline(resolved, line);) meta.emplace_back("config", line);
  write_pneumatic_dataset(file, report.data);
  report.file = file;
  report.rows = rows;
  return report;
}

}  // namespace tendril::envs::pneumatic
