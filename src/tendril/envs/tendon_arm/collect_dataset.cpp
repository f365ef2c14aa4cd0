#include "tendril/envs/tendon_arm/collect_dataset.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::tendon_arm {

namespace {

constexpr uint64_t kSignalStream = 0x7e4d51;

// `value` rounded to 1/scale: the file keeps what matters (1 µm, 0.1 mN) and stays short.
double rounded(double value, double scale) { return std::round(value * scale) / scale; }

// Appends `rows` rows of one recording to `table`: reset, then each row the observation and the
// tensions sent and held for one period.
void record(Env& robot, Rng& rng, const std::vector<double>& hold, int rows, double period,
            int split, std::vector<std::vector<double>>& out) {
  const int tendons = robot.action_space().size();
  const float max_tension = robot.action_space().high().maxCoeff();
  Observation observation = robot.reset(0);
  Eigen::VectorXd tensions = Eigen::VectorXd::Zero(tendons);
  double held_until = 0.0;
  for (int k = 0; k < rows; ++k) {
    const double time = rounded(k * period, 1e9);
    if (time >= held_until - 1e-9) {
      for (int j = 0; j < tendons; ++j) tensions[j] = rounded(rng.uniform(0.0, max_tension), 1e4);
      held_until = time + rng.uniform(hold[0], hold[1]);
    }
    std::vector<double> row{time};
    for (int j = 0; j < tendons; ++j) row.push_back(tensions[j]);
    for (int c = 0; c < 3 + tendons; ++c) row.push_back(rounded(observation[c], 1e6));
    row.push_back(split);
    out.push_back(std::move(row));
    if (k + 1 == rows) break;
    const Step step = robot.step(tensions.cast<float>());
    if (step.terminated || step.truncated) {
      throw Error("the robot ended the recording at t = " + std::to_string(time) + " s",
                  "tendon_arm::collect_dataset");
    }
    observation = step.observation;
  }
}

}  // namespace

data::TableSchema dataset_schema(int tendons) {
  using data::ColumnSpec;
  data::TableSchema schema;
  schema.format = "tendril.tendon_arm.data_set v1";
  schema.columns.push_back({"time_s", ColumnSpec::kShortest, {}, "s since the recording began"});
  for (int k = 1; k <= tendons; ++k) {
    schema.columns.push_back({"tension_" + std::to_string(k) + "_n",
                              ColumnSpec::kShortest,
                              {},
                              "N, sent at time_s and held until the next row"});
  }
  for (const char* axis : {"x", "y", "z"}) {
    schema.columns.push_back({std::string("tip_") + axis + "_m",
                              ColumnSpec::kShortest,
                              {},
                              "m, lab frame (origin at the clamped base, z up), measured"});
  }
  for (int k = 1; k <= tendons; ++k) {
    schema.columns.push_back(
        {"travel_" + std::to_string(k) + "_m",
         ColumnSpec::kShortest,
         {},
         "m reeled in from the unloaded straight arm's tendon length, measured"});
  }
  schema.columns.push_back({"split", 0, {"train", "test"}, "the recording the row belongs to"});
  return schema;
}

CollectionReport collect_dataset(const Config& config, const std::filesystem::path& output,
                                 const std::string& invocation) {
  const Config robot_config = config.child("robot");
  const std::string id = robot_config.get_or<std::string>("id", "TendonArm/Robot-v0");
  Config params = robot_config.child("params");
  const double period = params.get_or<double>("control_period_s", 0.1);
  const double duration = config.get_or<double>("duration_s", 300.0);
  const double test_duration = config.get_or<double>("test_duration_s", 60.0);
  if (!(std::isfinite(duration) && duration > 0.0)) {
    throw Error("must be positive", config.where("duration_s"));
  }
  if (!(std::isfinite(test_duration) && test_duration >= 0.0)) {
    throw Error("must be non-negative", config.where("test_duration_s"));
  }
  const uint64_t seed = config.get_or<uint64_t>("seed", 0);
  const Config signal = config.child("signal");
  const std::vector<double> hold =
      signal.get_or<std::vector<double>>("hold_s", std::vector<double>{0.2, 2.0});
  if (hold.size() != 2 || !(hold[0] > 0.0 && hold[1] >= hold[0] && std::isfinite(hold[1]))) {
    throw Error("needs [shortest, longest] with 0 < shortest <= longest", signal.where("hold_s"));
  }
  const std::string configured = config.get_or<std::string>("output", "");
  const std::filesystem::path file = output.empty() ? std::filesystem::path(configured) : output;
  if (file.empty()) throw Error("no output file: set `output` or pass --out", config.source());
  if (std::filesystem::exists(file)) {
    throw Error("the data set file exists; nothing was overwritten", file.string());
  }
  const int train_rows = static_cast<int>(std::lround(duration / period));
  const int test_rows = static_cast<int>(std::lround(test_duration / period));
  if (!params.has("max_episode_steps")) {
    params.set("max_episode_steps", std::to_string(std::max(train_rows, test_rows) + 1));
  }
  const std::unique_ptr<Env> robot = make(id, params);  // rejects unknown robot parameters
  config.reject_unknown();
  require(robot->action_space().is_box() &&
              robot->observation_space().size() == 3 + robot->action_space().size(),
          "the robot must take tensions and observe the tip and one travel per tendon", id);

  Rng rng(seed, kSignalStream);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<double>> rows;
  record(*robot, rng, hold, train_rows, period, 0, rows);
  if (test_rows > 0) record(*robot, rng, hold, test_rows, period, 1, rows);
  CollectionReport report;
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const int tendons = robot->action_space().size();
  const data::TableSchema schema = dataset_schema(tendons);
  data::Table& table = report.table;
  table.values.resize(static_cast<Eigen::Index>(rows.size()),
                      static_cast<Eigen::Index>(schema.columns.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < rows[r].size(); ++c) table.values(r, c) = rows[r][c];
  }
  table.set("protocol", "random tensions, each U[0, max], held U[hold_s] s (babbling)");
  table.set("command", invocation);
  table.set("robot", id);
  table.set("rows", std::to_string(rows.size()));
  std::ostringstream period_text;
  period_text << period;
  table.set("period_s", period_text.str());
  table.set("resolution", "positions 1 um, tensions 0.1 mN");
  std::istringstream resolved(config.dump());
  for (std::string line; std::getline(resolved, line);) table.metadata.emplace_back("config", line);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  data::write_table(file, table, schema);
  report.file = file;
  report.train_rows = train_rows;
  report.test_rows = test_rows;
  return report;
}

}  // namespace tendril::envs::tendon_arm
