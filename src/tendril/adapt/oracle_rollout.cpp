#include "tendril/adapt/oracle_rollout.hpp"

#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

// Steps `robot` from a reset with the commands `next_command` gives until it returns none, the
// goal, a collision or `max_steps`.
template <typename NextCommand>
OracleEpisode record(ReachingRobot& robot, int max_steps, std::optional<uint64_t> seed,
                     NextCommand next_command) {
  std::vector<Eigen::VectorXd> states{robot.reset(seed)}, commands;
  OracleEpisode episode;
  for (int t = 0; t < max_steps; ++t) {
    states.push_back(robot.step(next_command(t, states.back())));
    commands.push_back(robot.command());
    episode.statuses.push_back(robot.status());
    if (robot.status().success || robot.status().collision) break;
  }
  episode.states.resize(static_cast<Eigen::Index>(states.size()), robot.state_dim());
  for (std::size_t t = 0; t < states.size(); ++t) episode.states.row(t) = states[t].transpose();
  episode.commands.resize(static_cast<Eigen::Index>(commands.size()), robot.command_dim());
  for (std::size_t t = 0; t < commands.size(); ++t) {
    episode.commands.row(t) = commands[t].transpose();
  }
  return episode;
}

}  // namespace

OracleEpisode run_oracle(ReachingRobot& robot, const rl::Policy& policy, int max_steps,
                         std::optional<uint64_t> seed) {
  require(max_steps >= 1, "max_steps must be at least 1", "adapt::run_oracle");
  Rng unused(0);  // a deterministic policy draws nothing
  return record(robot, max_steps, seed, [&](int, const Eigen::VectorXd& state) {
    return robot.command_after(policy.act(robot.observation_of(state), true, unused));
  });
}

OracleEpisode replay_commands(ReachingRobot& robot, const Eigen::MatrixXd& commands,
                              std::optional<uint64_t> seed) {
  require(commands.rows() >= 1 && commands.cols() == robot.command_dim(),
          "replay needs at least one command of the robot's size", "adapt::replay_commands");
  return record(robot, static_cast<int>(commands.rows()), seed,
                [&](int t, const Eigen::VectorXd&) -> Eigen::VectorXd {
                  return commands.row(t).transpose();
                });
}

double reduced_accuracy_return(const std::vector<ReachStatus>& statuses, double radius) {
  double total = 0.0;
  for (const ReachStatus& s : statuses) {
    total -= 2.0;
    if (s.outside) total -= 100.0;
    if (s.obstacle_distance > 10.0 && s.obstacle_distance <= 20.0) {
      total -= 5.0 * (20.0 - s.obstacle_distance);
    }
    if (s.collision) total -= 10000.0;
    if (s.goal_distance > radius) total -= s.goal_distance;
  }
  return total;
}

void log_oracle_episode(const OracleEpisode& episode, int trial,
                        std::vector<AdaptationStep>& steps) {
  for (std::size_t t = 0; t < episode.statuses.size(); ++t) {
    AdaptationStep step;
    step.trial = trial;
    step.step = static_cast<int>(t);
    step.state = episode.states.row(t + 1).transpose();
    step.command = episode.commands.row(t).transpose();
    step.reference = episode.states.row(t).transpose();
    step.status = episode.statuses[t];
    steps.push_back(std::move(step));
  }
}

}  // namespace tendril::adapt
