// The SMA limb's data protocols (`tendril data ...`): calibrate it, collect its data sets,
// replay open-loop inputs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "collect_support.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/core/scene.hpp"
#include "tendril/data/limb_data_set.hpp"
#include "tendril/data/prepare.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/calibrate.hpp"
#include "tendril/envs/sma_limb/collect.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#include "tendril/envs/sma_limb/twin_limb_robot.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;
using namespace collect;
using envs::sma_limb::LimbLog;

// task: calibrate — the autonomous calibration of input bounds on the twin (seed 001, §4.2.1).
int calibrate(const Config& config) {
  const Config robot_config = config.child("robot");
  const std::string limb = robot_config.get_or<std::string>("limb", "stiff");
  physics::SmaLimbSpec spec = physics::SmaLimbSpec::variant(limb);
  spec.tip_mass = robot_config.get_or<double>("tip_mass", 0.0);
  const Config settings_config = config.child("calibration");
  envs::sma_limb::CalibrationSettings settings;
  settings.rest_s = settings_config.get_or<double>("rest_s", settings.rest_s);
  settings.hold_s = settings_config.get_or<double>("hold_s", settings.hold_s);
  settings.cooldown_s = settings_config.get_or<double>("cooldown_s", settings.cooldown_s);
  settings.start_pwm = settings_config.get_or<int>("start_pwm", settings.start_pwm);
  settings.max_pwm = settings_config.get_or<int>("max_pwm", settings.max_pwm);
  settings.velocity_window =
      settings_config.get_or<int>("velocity_window", settings.velocity_window);
  settings.noise_margin = settings_config.get_or<double>("noise_margin", settings.noise_margin);
  const uint64_t seed = config.get<uint64_t>("seed");
  const fs::path output = new_output(config, "output");
  const fs::path curves = new_output(config, "curves");
  config.reject_unknown();

  std::printf("tendril data calibrate: the %s limb twin (holds %.1f s, cool-downs %.0f s)\n",
              limb.c_str(), settings.hold_s, settings.cooldown_s);
  std::fflush(stdout);
  const Stopwatch stopwatch;
  envs::sma_limb::TwinLimbRobot robot(spec);
  // Each stage's result as it comes: the zero offsets in a moment, then each coil's sweep in
  // tens of seconds (the ETA counts the four sweeps).
  const ProgressClock clock;
  const auto report_stage = [&clock](int coil, const envs::sma_limb::LimbCalibration& calibration) {
    const int sweeps_done = coil + 1;
    if (coil < 0) {
      std::printf("zero offsets %.2f, %.2f deg; velocity noise floor %.2f deg/s\n",
                  calibration.zero_offset_deg.x(), calibration.zero_offset_deg.y(),
                  calibration.noise_floor_deg_s);
    } else {
      std::printf("coil %-5s lower PWM %3d (%4.1f %%)  upper PWM %3d (%4.1f %%)\n",
                  envs::sma_limb::LimbCalibration::kCoilKeys[coil], calibration.lower_pwm[coil],
                  100.0 * calibration.lower_pwm[coil] / 255.0, calibration.upper_pwm[coil],
                  100.0 * calibration.upper_pwm[coil] / 255.0);
    }
    std::printf("  (%d of 4 coils swept; %s)\n", sweeps_done,
                clock.text(sweeps_done / 4.0).c_str());
    std::fflush(stdout);
  };
  const envs::sma_limb::CalibrationResult result =
      envs::sma_limb::calibrate(robot, settings, limb, seed, report_stage);
  const envs::sma_limb::LimbCalibration& calibration = result.calibration;
  stopwatch.report(result.robot_time_s);
  calibration.save(output);

  // Fig. 4.1: every hold's curve along its coil's direction.
  const data::TableSchema schema{
      "tendril.sma_limb.calibration_curves v1",
      {{"coil", 0, {"pos_x", "neg_x", "pos_y", "neg_y"}, "the coil held on"},
       {"pwm", 0, {}, "its PWM during the hold, of 255"},
       {"time_s", 3, {}, "since the hold began, s"},
       {"angle_deg", 2, {}, "bend along the coil's direction, deg (zero offset removed)"},
       {"lower", 0, {}, "1 on the hold that set the coil's lower bound"},
       {"upper", 0, {}, "1 on the hold that set the coil's upper bound"}}};
  data::Table table;
  table.set("limb", limb);
  table.set("seed", std::to_string(seed));
  table.set("calibration", output.string());
  std::vector<std::array<double, 6>> rows;
  for (const auto& hold : result.holds) {
    const bool lower = hold.pwm == calibration.lower_pwm[hold.coil];
    const bool upper = hold.pwm == calibration.upper_pwm[hold.coil];
    for (std::size_t k = 0; k < hold.time_s.size(); ++k) {
      rows.push_back({static_cast<double>(hold.coil), static_cast<double>(hold.pwm),
                      std::round(hold.time_s[k] * 1e3) / 1e3, hold.angle_deg[k], lower ? 1.0 : 0.0,
                      upper ? 1.0 : 0.0});
    }
  }
  table.values.resize(static_cast<Eigen::Index>(rows.size()), 6);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (int c = 0; c < 6; ++c) table.values(static_cast<Eigen::Index>(r), c) = rows[r][c];
  }
  data::write_table(curves, table, schema);
  std::printf("wrote %s and %s\n", output.c_str(), curves.c_str());
  return 0;
}

// task: explore | babble — a data set (seed 001, §4.2.2, §4.2.3), optionally prepared.
int collect_data(const Config& config, const std::string& task) {
  const envs::sma_limb::CollectSettings settings = collect_settings(config);
  const uint64_t seed = config.get<uint64_t>("seed");
  auto source = throttle_source(task, config);
  auto env = limb_env(config);
  const Config env_config = config.child("env");
  const std::string limb = env_config.get_or<std::string>("limb", "stiff");
  const std::string calibration = env_config.get_or<std::string>("calibration", "nominal");
  const fs::path output = new_output(config, "output");
  const Config prepare_config = config.child("prepare");
  fs::path prepared_output;
  data::PrepareSettings prepare;
  if (config.has("prepare")) {
    prepared_output = new_output(prepare_config, "output");
    prepare.ema_alpha = prepare_config.get_or<double>("ema_alpha", prepare.ema_alpha);
    prepare.test_fraction = prepare_config.get_or<double>("test_fraction", prepare.test_fraction);
    prepare.max_gap_s = prepare_config.get_or<double>("max_gap_s", prepare.max_gap_s);
  }
  const double window_s = config.get_or<double>("coverage_window_s", 600.0);
  config.reject_unknown();

  std::printf("tendril data collect: %s on the %s limb for %.0f s of robot time\n", task.c_str(),
              limb.c_str(), settings.duration_s);
  const Stopwatch stopwatch;
  RobotTimeProgress progress(settings.duration_s);
  const LimbLog log = envs::sma_limb::collect(*env, *source, settings, seed, std::ref(progress));
  progress.finish();
  stopwatch.report(log.time_s.back());
  for (double until : {window_s, settings.duration_s}) {
    const auto grid = coverage(log, until);
    std::printf(
        "coverage of the 6x6 grid over +-100 deg, first %.0f s: %d of 36 cells, "
        "evenness %.3f\n",
        until, grid.visited_cells(), grid.evenness());
    if (until >= settings.duration_s) break;
  }
  std::printf("%zu readings, %lld past the cut-off\n", log.size(),
              static_cast<long long>(log.cutoffs));
  // What a simulated robot reports of itself at the end (coil temperatures, wear, ...).
  Scene scene;
  if (env->describe_scene(scene)) {
    std::printf("the robot at the end:");
    for (const auto& [name, value] : scene.values) std::printf(" %s %.4g;", name.c_str(), value);
    std::printf("\n");
  }

  data::Table table = log_table(log);
  table.set("robot", std::string(envs::sma_limb::SmaLimbEnv::kId) + ", the physics twin");
  table.set("limb", limb);
  table.set("calibration", calibration);
  table.set("collector", task == "babble" ? "motor babbling (the author's babbling firmware)"
                                          : "count-based exploration (Algorithm 1), rule " +
                                                config.get_or<std::string>("rule", "random_walk"));
  table.set("seed", std::to_string(seed));
  table.set("hold_readings", std::to_string(settings.hold_readings));
  table.set("cutoff_cooldown_s", number(settings.cutoff_cooldown_s));
  // A twin re-damped or with another phase model, for a study, is another limb: its data set
  // says so.
  if (env_config.has("damping_rate")) {
    table.set("damping_rate_per_s", number(env_config.get<double>("damping_rate")));
  }
  if (env_config.has("phase_reentry")) {
    table.set("phase_reentry", env_config.get<std::string>("phase_reentry"));
  }
  table.set("config", config.source());
  data::write_limb_data_set(output, table);
  std::printf("wrote %s\n", output.c_str());
  if (!prepared_output.empty()) {
    table.set("data_set", output.string());
    const data::Table prepared = data::prepare_limb_data(table, prepare);
    data::write_prepared(prepared_output, prepared);
    std::printf("wrote %s (split at %s s)\n", prepared_output.c_str(),
                prepared.get("split_time_s").c_str());
  }
  return 0;
}

}  // namespace

int limb_protocol(const Arguments& line, const std::vector<std::string>& tasks) {
  const Config config = line.load_config(file_kind::kDataProtocol);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines appear as they are printed
  const std::string task = config.get<std::string>("task");
  if (std::find(tasks.begin(), tasks.end(), task) == tasks.end()) {
    std::string expected;
    for (const std::string& t : tasks) expected += (expected.empty() ? "" : " or ") + t;
    throw Error("the file describes a '" + task + "' protocol; this command runs " + expected +
                    " (tendril data --help lists the protocols)",
                where(config, "task"));
  }
  if (task == "calibrate") return calibrate(config);
  if (task == "explore" || task == "babble") return collect_data(config, task);
  if (task == "replay") return collect::replay(config);
  if (task == "coverage") return collect::compare_coverage(config);
  if (task == "open_loop") return collect::open_loop(config);
  throw Error(
      "unknown task '" + task + "' (calibrate, explore, babble, replay, coverage, open_loop)",
      where(config, "task"));
}

}  // namespace tendril::apps
