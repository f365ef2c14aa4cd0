#include "tendril/adapt/gprca_trials.hpp"

#include "tendril/core/error.hpp"

namespace tendril::adapt {

AdaptationResult run_gprca(ReachingRobot& robot, RobotHistoryModel& model, const rl::Policy& policy,
                           const GprcaTrialsOptions& options, uint64_t seed) {
  require(options.max_trials >= 1 && options.steps_per_trial >= 1 && options.trials_after_goal >= 0,
          "max_trials and steps_per_trial must be at least 1, trials_after_goal non-negative",
          "adapt::run_gprca");
  CompensationOptions compensator_options = options.compensator;
  compensator_options.steps_per_episode = options.steps_per_trial;
  GprcaCompensator compensator(robot.command_dim(), robot.state_dim(), compensator_options);
  Rng policy_rng(seed, 0x6770);  // unused by a deterministic policy; act() takes one

  AdaptationResult result;
  int trial = 0;
  Eigen::VectorXd command;  // τ_t of the step under way
  std::vector<ReachStatus> statuses;
  std::vector<Eigen::VectorXd> held;  // the command the robot held in each step

  CompensationLoop loop;
  loop.reset = [&]() -> Eigen::VectorXd {
    const Eigen::VectorXd rest =
        robot.reset(trial == 1 ? std::optional<uint64_t>(seed) : std::nullopt);
    model.reset(rest);
    return rest;
  };
  loop.policy = [&](const Eigen::VectorXd& compensated) -> Eigen::VectorXd {
    const Action action = policy.act(robot.observation_of(compensated), true, policy_rng);
    command = robot.command_after(action);
    return options.input == CompensatorInput::command ? command : action.cast<double>();
  };
  // x̂_{t+1} = F_φ([x_t, x_{t−1}], τ_t): the model's history is the robot's (follow below).
  loop.model = [&](const Eigen::VectorXd&, const Eigen::VectorXd&,
                   const Eigen::VectorXd&) -> Eigen::VectorXd { return model.predict(command); };
  loop.step = [&](const Eigen::VectorXd&) -> Eigen::VectorXd {
    const Eigen::VectorXd next = robot.step(command);
    model.follow(next);
    statuses.push_back(robot.status());
    held.push_back(robot.command());
    return next;
  };
  loop.finished = [&](const Eigen::VectorXd&) {
    return robot.status().success || robot.status().collision;
  };

  int trials_after = 0;
  while (trial < options.max_trials) {
    ++trial;
    statuses.clear();
    held.clear();
    const std::vector<CompensationStep> steps = compensator.run_episode(loop);
    const std::size_t first = result.steps.size();
    for (std::size_t t = 0; t < steps.size(); ++t) {
      AdaptationStep logged;
      logged.trial = trial;
      logged.step = static_cast<int>(t);
      logged.state = steps[t].next_observation;
      logged.reference = steps[t].observation + steps[t].compensation;
      logged.command = held[t];
      logged.status = statuses[t];
      logged.update_seconds = steps[t].update_seconds;
      result.steps.push_back(std::move(logged));
    }
    AdaptationTrial summary = summarize_trial(trial, "gprca", result.steps, first);
    if (options.search_between_trials)
      summary.search_seconds = compensator.search_hyperparameters();
    result.trials.push_back(summary);
    if (result.goal_flag) {
      ++trials_after;
    } else if (summary.success) {
      result.goal_flag = true;
      result.trials_to_goal = trial;
    }
    if (result.goal_flag && trials_after >= options.trials_after_goal) break;
  }
  if (!result.goal_flag) result.trials_to_goal = trial;
  return result;
}

}  // namespace tendril::adapt
