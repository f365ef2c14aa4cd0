#include "collect_support.hpp"

#include <cmath>
#include <cstdio>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"

namespace tendril::apps::collect {

Stopwatch::Stopwatch() : wall_(std::chrono::steady_clock::now()), cpu_(std::clock()) {}

void RobotTimeProgress::operator()(double robot_time_s) {
  const double now = clock_.elapsed_s();
  if (last_print_s_ >= 0.0 && now - last_print_s_ < 1.0) return;
  last_print_s_ = now;
  std::fprintf(stderr, "\rrobot time %.0f/%.0f s (%.1f%%)  %s   ", robot_time_s, robot_s_,
               100.0 * robot_time_s / robot_s_, clock_.text(robot_time_s / robot_s_).c_str());
  std::fflush(stderr);
}

void RobotTimeProgress::finish() const {
  if (last_print_s_ < 0.0) return;
  std::fputc('\n', stderr);
}

void Stopwatch::report(double robot_s) const {
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
  const double cpu = static_cast<double>(std::clock() - cpu_) / CLOCKS_PER_SEC;
  std::printf(
      "robot time %.1f s (%.1f min) in %.1f s wall, %.1f s CPU: %.0fx real time "
      "(wall), %.0fx (CPU)\n",
      robot_s, robot_s / 60.0, wall, cpu, robot_s / wall, robot_s / cpu);
}

std::string where(const Config& config, const std::string& key) {
  return config.source() + ": " + (config.path().empty() ? "" : config.path() + ".") + key;
}

std::filesystem::path new_output(const Config& config, const std::string& key) {
  const std::filesystem::path file = config.get<std::string>(key);
  if (std::filesystem::exists(file))
    throw Error("exists already; not overwriting it", file.string());
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  return file;
}

std::unique_ptr<Env> limb_env(const Config& config) {
  return envs::make(envs::sma_limb::SmaLimbEnv::kId, config.child("env"));
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

data::Table log_table(const envs::sma_limb::LimbLog& log) {
  data::Table table;
  table.values.resize(static_cast<Eigen::Index>(log.size()), 9);
  for (std::size_t k = 0; k < log.size(); ++k) {
    const auto r = static_cast<Eigen::Index>(k);
    // Readings carry 0.01° (0.1° sensor steps less 0.01° offsets); stamps whole milliseconds.
    table.values.row(r) << std::round(log.time_s[k] * 1e3) / 1e3,
        std::round(log.angles_deg[k].x() * 100.0) / 100.0,
        std::round(log.angles_deg[k].y() * 100.0) / 100.0, log.throttles[k].x(),
        log.throttles[k].y(), log.pwm[k][0], log.pwm[k][1], log.pwm[k][2], log.pwm[k][3];
  }
  return table;
}

envs::sma_limb::VisitGrid coverage(const envs::sma_limb::LimbLog& log, double until_s) {
  envs::sma_limb::VisitGrid grid;
  for (std::size_t k = 0; k < log.size() && log.time_s[k] < until_s; ++k) {
    grid.visit(log.angles_deg[k]);
  }
  return grid;
}

envs::sma_limb::CollectSettings collect_settings(const Config& config) {
  envs::sma_limb::CollectSettings settings;
  settings.duration_s = config.get<double>("duration_s");
  settings.hold_readings = config.get_or<int>("hold_readings", settings.hold_readings);
  settings.cutoff_cooldown_s =
      config.get_or<double>("cutoff_cooldown_s", settings.cutoff_cooldown_s);
  return settings;
}

std::unique_ptr<envs::sma_limb::ThrottleSource> throttle_source(const std::string& task,
                                                                const Config& config) {
  using envs::sma_limb::CountBasedExploration;
  if (task == "babble") return std::make_unique<envs::sma_limb::MotorBabbling>();
  const std::string rule = config.get_or<std::string>("rule", "random_walk");
  if (rule != "random_walk" && rule != "uniform") {
    throw Error("rule must be random_walk or uniform, got '" + rule + "'", where(config, "rule"));
  }
  return std::make_unique<CountBasedExploration>(rule == "uniform"
                                                     ? CountBasedExploration::Rule::kUniform
                                                     : CountBasedExploration::Rule::kRandomWalk);
}

}  // namespace tendril::apps::collect
