#include "tendril/safety/diamond_deployment.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/learned_safety_env.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_evaluation.hpp"

namespace tendril::safety {

using envs::sma_limb::LearnedSafetyEnv;

int diamond_move(double seconds) {
  // (move, seconds): u1 3 s, u4 3 s, u3 6 s, u2 12 s, u1 6 s, u3 3 s; moves 0–3 are u1–u4.
  static const std::pair<int, double> segments[] = {{0, 3.0},  {3, 3.0}, {2, 6.0},
                                                    {1, 12.0}, {0, 6.0}, {2, 3.0}};
  double end = 0.0;
  for (const auto& [move, duration] : segments) {
    end += duration;
    if (seconds < end) return move;
  }
  return -1;
}

std::vector<DiamondTrial> run_diamond(const std::filesystem::path& critic_run,
                                      const DiamondOptions& options) {
  require(options.trials >= 1 && !options.epsilons.empty(), "at least one trial and one ε₂ value",
          "run_diamond");
  const rl::Experiment run = task_experiment_of_run(critic_run);
  auto model_env = envs::make(run.env.id, run.env.params);
  const auto* limb_task = envs::find_wrapper<LearnedSafetyEnv>(*model_env);
  require(limb_task != nullptr, "the critic's run is not on " + std::string(LearnedSafetyEnv::kId),
          critic_run.string());
  const LearnedSafetyEnv::Params task = limb_task->params();
  const auto critic = load_safety_critic(critic_run / "safety.critic");

  std::vector<DiamondTrial> trials;
  for (double epsilon : options.epsilons) {
    for (int k = 0; k < options.trials; ++k) {
      auto limb = envs::make("SmaLimb/Robot-v0", options.limb_params);
      Observation reading = limb->reset(options.seed + static_cast<uint64_t>(k));
      const double start_s = reading[2];
      Eigen::Vector2d previous_angles(reading[0], reading[1]);
      double previous_s = start_s;
      DiamondTrial trial;
      trial.epsilon = epsilon;
      trial.trial = k;
      trial.time_to_violation_s = std::numeric_limits<double>::quiet_NaN();
      std::vector<Eigen::Matrix<double, 7, 1>> rows;
      int64_t steps = 0, interventions = 0;
      Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
      for (;;) {
        const double elapsed = reading[2] - start_s;
        const Eigen::Vector2d angles(reading[0], reading[1]);
        if (std::isnan(trial.time_to_violation_s) &&
            LearnedSafetyEnv::safety_margin(task, angles[0], angles[1]) <= 0.0) {
          trial.time_to_violation_s = elapsed;
        }
        const int nominal = diamond_move(elapsed);
        if (nominal < 0) break;
        Observation x(5);
        x << angles.cast<float>(), velocity.cast<float>(),
            static_cast<float>(std::min<double>(1.0, static_cast<double>(steps) / task.horizon));
        const double value = critic->value(x, Action::Constant(1, static_cast<float>(nominal)));
        const bool intervene = value <= epsilon;
        const int move = intervene ? static_cast<int>(critic->safe_action(x)[0]) : nominal;
        const Eigen::Vector2d throttles = LearnedSafetyEnv::throttles(move);
        Eigen::Matrix<double, 7, 1> row;
        row << elapsed, angles[0], angles[1], value, intervene ? 1.0 : 0.0, throttles[0],
            throttles[1];
        rows.push_back(row);
        interventions += intervene ? 1 : 0;
        const Step step = limb->step(throttles.cast<float>());
        reading = step.observation;
        ++steps;
        const double dt = reading[2] - previous_s;
        const Eigen::Vector2d now(reading[0], reading[1]);
        if (dt > 0.0) velocity = (now - previous_angles) / dt;
        previous_angles = now;
        previous_s = reading[2];
        require(!step.terminated, "the twin's state became non-finite", "run_diamond");
      }
      trial.intervention_rate =
          steps == 0 ? 0.0 : static_cast<double>(interventions) / static_cast<double>(steps);
      trial.trajectory.resize(static_cast<Eigen::Index>(rows.size()), 7);
      for (std::size_t i = 0; i < rows.size(); ++i) {
        trial.trajectory.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
      }
      trials.push_back(std::move(trial));
    }
  }
  return trials;
}

}  // namespace tendril::safety
