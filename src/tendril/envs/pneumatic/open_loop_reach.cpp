#include "tendril/envs/pneumatic/open_loop_reach.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/envs/pneumatic/decimal_text.hpp"
#include "tendril/envs/pneumatic/reach_task.hpp"
#include "tendril/envs/pneumatic/robot_env.hpp"

namespace tendril::envs::pneumatic {

namespace {

constexpr int kEpisodeSteps = 150;
constexpr double kRateLimitBar = 0.15;  // per 0.1 s step (seed 002 §IV-A3)
constexpr int kSettleSteps = 30;        // 3 s at 0.1 s: a static response for the search

Eigen::Vector3d module_3_tip(const Observation& observation) {
  return observation.segment<3>(6).cast<double>();
}

// Runs the ramp-and-hold plan toward `pressures` for `steps` steps; module 3's final tip.
Eigen::Vector3d run_plan(Env& arm, const ChamberVector& pressures, int steps,
                         std::optional<uint64_t> seed) {
  arm.reset(seed);
  Observation observation;
  for (int k = 0; k < steps; ++k) {
    const ChamberVector commands = pressures.cwiseMin(kRateLimitBar * (k + 1));
    observation = arm.step(commands.cast<float>()).observation;
  }
  return module_3_tip(observation);
}

}  // namespace

OpenLoopOptions open_loop_options(const Config& open_loop) {
  OpenLoopOptions options;
  options.goals = open_loop.get_or<std::vector<std::string>>("goals", options.goals);
  for (const std::string& goal : options.goals)
    ReachTaskSpec::preset(goal, key_where(open_loop, "goals"));
  options.trials = open_loop.get_or<int>("trials", options.trials);
  options.search_evaluations =
      open_loop.get_or<int>("search_evaluations", options.search_evaluations);
  options.seed = open_loop.get_or<uint64_t>("seed", options.seed);
  if (options.trials < 1) throw Error("must be at least 1", key_where(open_loop, "trials"));
  if (options.search_evaluations < 1) {
    throw Error("must be at least 1", key_where(open_loop, "search_evaluations"));
  }
  return options;
}

OpenLoopReport open_loop_reach(const Config& robot_params,
                               const std::vector<std::string>& scenarios,
                               const OpenLoopOptions& options) {
  const auto& names = options.goals;
  const int trials = options.trials;
  const int evaluations = options.search_evaluations;
  const uint64_t seed = options.seed;

  const physics::pneumatic::PneumaticArmSpec twin = arm_spec_from(robot_params);
  physics::pneumatic::PneumaticArmSpec model_spec = twin;
  model_spec.scenario = physics::pneumatic::DamageScenario::kS0;
  model_spec.effects.drift = model_spec.effects.hysteresis = false;
  model_spec.effects.sensor_noise = false;
  model_spec.effects.elasticity = false;  // the nominal elasticity
  RobotEnv model(model_spec, 0.1, false);

  const auto start = std::chrono::steady_clock::now();
  OpenLoopReport report;
  for (const std::string& name : names) {
    OpenLoopReport::Goal goal;
    goal.name = name;
    goal.position = ReachTaskSpec::preset(name).goal;
    // Random search: perturb a random subset of the best pressures, shrinking the step.
    Rng rng(seed, 0x90a1u);
    ChamberVector best = ChamberVector::Constant(0.5);
    double best_distance = (run_plan(model, best, kSettleSteps, 0) - goal.position).norm();
    double step = 0.5;
    for (int e = 1; e < evaluations; ++e) {
      ChamberVector candidate = best;
      for (int k = 0; k < 9; ++k) {
        if (rng.uniform() < 0.4) candidate[k] = std::clamp(best[k] + step * rng.normal(), 0.0, 1.5);
      }
      const double distance = (run_plan(model, candidate, kSettleSteps, 0) - goal.position).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = candidate;
      }
      if (e % std::max(1, evaluations / 6) == 0) step *= 0.6;
    }
    goal.pressures = best;
    goal.model_distance = (run_plan(model, best, kEpisodeSteps, 0) - goal.position).norm();
    report.goals.push_back(goal);
  }

  for (const std::string& scenario : scenarios) {
    physics::pneumatic::PneumaticArmSpec spec = twin;
    spec.scenario = physics::pneumatic::parse_damage_scenario(scenario, "scenarios");
    RobotEnv arm(spec, 0.1, false);
    for (const OpenLoopReport::Goal& goal : report.goals) {
      for (int trial = 0; trial < trials; ++trial) {
        const Eigen::Vector3d tip =
            run_plan(arm, goal.pressures, kEpisodeSteps,
                     trial == 0 ? std::optional<uint64_t>(seed) : std::nullopt);
        report.rows.push_back({scenario, goal.name, trial + 1, (tip - goal.position).norm()});
      }
    }
  }
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

void write_open_loop_report(const OpenLoopReport& report, const std::filesystem::path& directory,
                            const std::string& invocation) {
  const auto file = directory / "open_loop_reach.csv";
  require(!std::filesystem::exists(file), "the file exists; nothing was overwritten",
          file.string());
  std::string text = "# " + invocation + "\n";
  for (const OpenLoopReport::Goal& goal : report.goals) {
    text += "# goal ";
    text += goal.name;
    text += ": p* [bar] =";
    for (int k = 0; k < 9; ++k) {
      text += ' ';
      text += shortest_text(rounded(goal.pressures[k], 1e4));
    }
    text += "; model's final distance ";
    text += shortest_text(rounded(goal.model_distance, 1e3));
    text += " mm\n";
  }
  text += "scenario,goal,trial,final_distance_mm\n";
  for (const OpenLoopReport::Row& row : report.rows) {
    text += row.scenario;
    text += ',';
    text += row.goal;
    text += ',';
    text += std::to_string(row.trial);
    text += ',';
    text += shortest_text(rounded(row.final_distance_mm, 1e3));
    text += '\n';
  }
  std::filesystem::create_directories(directory);
  write_file_atomically(file, text, "open-loop report");
}

}  // namespace tendril::envs::pneumatic
