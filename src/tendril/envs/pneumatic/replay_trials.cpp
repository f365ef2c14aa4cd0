#include "tendril/envs/pneumatic/replay_trials.hpp"

#include <chrono>
#include <cmath>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/envs/pneumatic/decimal_text.hpp"
#include "tendril/envs/pneumatic/model_dynamics.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"
#include "tendril/envs/pneumatic/saturating_signal.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::pneumatic {

namespace {

using Trajectory = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>;  // steps × tips

// Mean over steps of module m's tip distance between two trajectories.
double mad(const Trajectory& a, const Trajectory& b, int module) {
  return (a.middleCols<3>(3 * module) - b.middleCols<3>(3 * module)).rowwise().norm().mean();
}

}  // namespace

ReplayReport replay_trials(const Config& config) {
  const Config robot_config = config.child("robot");
  const std::string id = robot_config.get_or<std::string>("id", "PneumaticArm/Robot-v0");
  Config params = robot_config.child("params");
  const std::vector<std::string> scenarios =
      config.get_or<std::vector<std::string>>("scenarios", {"S0", "S1", "S2", "S3", "S4"});
  const int trials = config.get_or<int>("trials", 10);
  const double duration = config.get_or<double>("duration_s", 30.0);
  const uint64_t seed = config.get_or<uint64_t>("seed", 0);
  const double period = params.get_or<double>("control_period_s", 0.1);
  if (scenarios.empty()) throw Error("list at least one scenario", key_where(config, "scenarios"));
  if (trials < 1) throw Error("must be at least 1", key_where(config, "trials"));
  if (!(std::isfinite(duration) && duration > 0.0 && std::isfinite(period) && period > 0.0)) {
    throw Error("must be positive", key_where(config, "duration_s"));
  }
  const int steps = static_cast<int>(std::lround(duration / period));
  const SaturatingSignalSpec signal_spec = saturating_signal_from(config.child("signal"));

  std::vector<Action> commands;
  SaturatingSignal signal(signal_spec, Rng(seed, 0x5a7u));
  for (int k = 0; k < steps; ++k) commands.push_back(signal.next(period).cast<float>());

  const auto start = std::chrono::steady_clock::now();
  ReplayReport report;
  report.scenarios = scenarios;
  report.period = period;
  report.module_3_gap_mm =
      Eigen::MatrixXd::Zero(steps, static_cast<Eigen::Index>(scenarios.size()));
  Trajectory reference;
  const Config model_config = config.child("reference_model");
  const bool model_reference = config.has("reference_model");
  if (model_reference) {
    // Fig. 6 proper: the learned model run open loop on the commands, recursively on its own
    // predictions from the arm's rest.
    const std::string file = model_config.get<std::string>("rest_from");
    ModelDynamics model(load_dynamics_model(model_config.get<std::string>("model"),
                                            key_where(model_config, "model")),
                        read_pneumatic_dataset(file).tips_mm.row(0).transpose());
    model_config.reject_unknown();
    model.reset(std::nullopt);
    reference.resize(steps, 9);
    for (int k = 0; k < steps; ++k) {
      reference.row(k) = model.step(commands[k].cast<double>()).transpose();
      if (!model.finite()) throw Error("the model's prediction became non-finite", file);
    }
  }
  for (size_t s = 0; s < scenarios.size(); ++s) {
    params.set("scenario", scenarios[s]);
    if (!params.has("max_episode_steps"))
      params.set("max_episode_steps", std::to_string(steps + 1));
    const std::unique_ptr<Env> robot = make(id, params);
    if (s == 0) config.reject_unknown();
    std::vector<Trajectory> runs;
    for (int trial = 0; trial < trials; ++trial) {
      robot->reset(trial == 0 ? std::optional<uint64_t>(seed) : std::nullopt);
      Trajectory tips(steps, 9);
      for (int k = 0; k < steps; ++k) {
        const Step step = robot->step(commands[k]);
        if (step.terminated || step.truncated) {
          throw Error("the robot ended trial " + std::to_string(trial + 1) + " of " + scenarios[s] +
                          " early",
                      "replay_trials");
        }
        tips.row(k) = step.observation.head<9>().cast<double>().transpose();
      }
      runs.push_back(std::move(tips));
    }
    if (s == 0 && !model_reference) reference = runs[0];
    for (int trial = 0; trial < trials; ++trial) {
      for (int m = 0; m < 3; ++m) {
        report.rows.push_back({scenarios[s], trial + 1, m + 1, mad(runs[trial], reference, m),
                               mad(runs[trial], runs[0], m)});
      }
      report.module_3_gap_mm.col(static_cast<Eigen::Index>(s)) +=
          (runs[trial].rightCols<3>() - reference.rightCols<3>()).rowwise().norm() / trials;
    }
  }
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

void write_replay_report(const ReplayReport& report, const std::filesystem::path& directory,
                         const std::string& invocation) {
  const auto summary_file = directory / "replay_gap.csv";
  const auto series_file = directory / "replay_gap_series.csv";
  for (const auto& file : {summary_file, series_file}) {
    require(!std::filesystem::exists(file), "the file exists; nothing was overwritten",
            file.string());
  }
  std::string summary = "# " + invocation + "\n";
  summary += "scenario,trial,module,mad_from_reference_mm,mad_from_own_base_mm\n";
  for (const ReplayReport::Row& row : report.rows) {
    for (const std::string& field :
         {row.scenario, std::to_string(row.trial), std::to_string(row.module),
          shortest_text(rounded(row.mad_from_reference_mm, 1e3))}) {
      summary += field;
      summary += ',';
    }
    summary += shortest_text(rounded(row.mad_from_own_base_mm, 1e3));
    summary += '\n';
  }
  std::string series = "# " + invocation + "\ntime_s";
  for (const std::string& scenario : report.scenarios) {
    series += ",module3_gap_";
    series += scenario;
    series += "_mm";
  }
  series += "\n";
  for (Eigen::Index k = 0; k < report.module_3_gap_mm.rows(); ++k) {
    series += shortest_text(rounded((k + 1) * report.period, 1e9));
    for (Eigen::Index s = 0; s < report.module_3_gap_mm.cols(); ++s) {
      series += ',';
      series += shortest_text(rounded(report.module_3_gap_mm(k, s), 1e3));
    }
    series += "\n";
  }
  std::filesystem::create_directories(directory);
  write_file_atomically(summary_file, summary, "replay summary");
  write_file_atomically(series_file, series, "replay series");
}

}  // namespace tendril::envs::pneumatic
