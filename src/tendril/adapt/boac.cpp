#include "tendril/adapt/boac.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>

#include "tendril/adapt/oracle_rollout.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

constexpr const char* kWhere = "adapt::run_boac";

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void validate(const BoacOptions& options) {
  require(options.oracle_trials >= 1 && options.best_trials >= 1 &&
              options.best_trials <= options.oracle_trials,
          "best_trials must lie in [1, oracle_trials]", kWhere);
  require(options.oracle_steps >= 1 && options.coach_episodes >= 1,
          "oracle_steps and coach_episodes must be at least 1", kWhere);
  require(!options.profiles.empty(), "at least one coaching profile is needed", kWhere);
  for (double radius : options.profiles) {
    require(std::isfinite(radius) && radius > 0.0, "profiles must be positive radii", kWhere);
  }
  require(options.local_flag > 0.0 && options.batch >= 1 && options.hold_steps >= 0 &&
              options.max_trials_per_profile >= 1 && options.max_trials >= 1 &&
              options.offset_bound > 0.0 && options.collision_penalty >= 0.0,
          "local_flag, batch, the trial limits and offset_bound must be positive", kWhere);
}

std::string profile_name(double radius) {
  char text[32];
  std::snprintf(text, sizeof text, "coach %g mm", radius);
  return text;
}

// Lines 1–3: the oracle on the robot; the N best episodes by reduced-accuracy return train π_0.
void seed_student(ReachingRobot& robot, const rl::Policy& oracle,
                  const std::vector<OracleEpisode>& in_model, const BoacOptions& options,
                  uint64_t seed, StudentPolicy& student, AdaptationResult& result) {
  std::vector<OracleEpisode> episodes;
  std::vector<double> returns;
  for (int n = 0; n < options.oracle_trials; ++n) {
    const std::optional<uint64_t> trial_seed =
        n == 0 ? std::optional<uint64_t>(seed) : std::nullopt;
    episodes.push_back(
        options.oracle_open_loop
            ? replay_commands(robot, in_model[n % in_model.size()].commands, trial_seed)
            : run_oracle(robot, oracle, options.oracle_steps, trial_seed));
    returns.push_back(reduced_accuracy_return(episodes.back().statuses, options.profiles.front()));
    const std::size_t first = result.steps.size();
    log_oracle_episode(episodes.back(), n + 1, result.steps);
    result.trials.push_back(summarize_trial(n + 1, "oracle", result.steps, first));
  }
  std::vector<int> order(episodes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return returns[a] > returns[b]; });
  for (int k = 0; k < options.best_trials; ++k) {
    const OracleEpisode& episode = episodes[order[k]];
    for (Eigen::Index t = 0; t < episode.commands.rows(); ++t) {
      student.add(episode.states.row(t).transpose(), episode.states.row(t + 1).transpose(),
                  episode.commands.row(t).transpose());
    }
  }
}

// D_d: π_θ's deterministic episodes in the learned model.
std::vector<OracleEpisode> model_episodes(ReachingRobot& model, const rl::Policy& oracle,
                                          const BoacOptions& options, uint64_t seed) {
  std::vector<OracleEpisode> episodes;
  for (int e = 0; e < options.coach_episodes; ++e) {
    episodes.push_back(run_oracle(model, oracle, options.oracle_steps,
                                  e == 0 ? std::optional<uint64_t>(seed) : std::nullopt));
  }
  return episodes;
}

}  // namespace

GpOptions default_student_options() {
  GpOptions options;
  options.kernel = KernelType::squared_exponential;
  options.window = 600;
  options.restarts = 1;
  return options;
}

BayesOptOptions default_offset_optimizer_options() {
  BayesOptOptions options;
  options.initial_points = 3;
  options.acquisition = Acquisition::expected_improvement;
  return options;
}

AdaptationResult run_boac(ReachingRobot& robot, ReachingRobot& model, const rl::Policy& oracle,
                          const BoacOptions& options, uint64_t seed) {
  validate(options);
  require(model.state_dim() == robot.state_dim() && robot.state_dim() % 3 == 0,
          "the model and the robot must share a state of module triples", kWhere);
  Rng rng(seed, 0xB0AC);
  AdaptationResult result;
  StudentPolicy student(robot.state_dim(), robot.command_dim(), options.student, options.sharing);
  const std::vector<OracleEpisode> in_model = model_episodes(model, oracle, options, seed);
  seed_student(robot, oracle, in_model, options, seed, student, result);
  student.fit_hyperparameters(rng);
  std::vector<Eigen::MatrixXd> demonstrations;
  for (const OracleEpisode& episode : in_model) demonstrations.push_back(episode.states);

  int trial = 0;  // coaching trials so far
  for (std::size_t profile = 0; profile < options.profiles.size() && !result.goal_flag; ++profile) {
    const double radius = options.profiles[profile];
    const bool last_profile = profile + 1 == options.profiles.size();
    // Line 5: the coach's path for this profile.
    const Eigen::MatrixXd path =
        coach_path(demonstrations, robot.goal(), radius, options.coach, rng);
    const Eigen::Vector3d path_end = path.bottomRows<1>().rightCols<3>().transpose();
    BayesOptOptions bo_options = options.bayes_opt;
    bo_options.lower = Eigen::VectorXd::Constant(3, -options.offset_bound);
    bo_options.upper = Eigen::VectorXd::Constant(3, options.offset_bound);
    bo_options.seed = seed * 1000 + profile;
    BayesianOptimizer optimizer(bo_options);

    for (int in_profile = 0; in_profile < options.max_trials_per_profile; ++in_profile) {
      if (trial >= options.max_trials) break;
      ++trial;
      const int logged_trial = options.oracle_trials + trial;
      // Line 7: a coaching episode toward the path, shifted by the optimiser's offset.
      const Eigen::VectorXd offset = optimizer.ask();
      Eigen::MatrixXd targets = path;
      targets.rightCols<3>().rowwise() += offset.transpose();
      const int length = static_cast<int>(path.rows()) - 1 + options.hold_steps;
      Eigen::VectorXd state = robot.reset(std::nullopt);
      // The coach's path starts where the model's episodes did; the robot's rest lies elsewhere
      // (its drift). The path is moved onto the robot's start, the shift fading linearly to
      // nothing at the path's end, so the first targets are reachable steps.
      const Eigen::RowVectorXd start_shift = state.transpose() - path.row(0);
      for (Eigen::Index row = 0; row < targets.rows(); ++row) {
        const double fade =
            1.0 - static_cast<double>(row) /
                      static_cast<double>(std::max<Eigen::Index>(1, targets.rows() - 1));
        targets.row(row) += fade * start_shift;
      }
      std::vector<Eigen::VectorXd> pending_states, pending_next, pending_commands;
      const std::size_t first = result.steps.size();
      double squared_tracking = 0.0;
      for (int t = 0; t < std::max(length, 1); ++t) {
        const Eigen::Index row = std::min<Eigen::Index>(t + 1, path.rows() - 1);
        const Eigen::VectorXd desired = targets.row(row).transpose();
        const auto start = std::chrono::steady_clock::now();
        const Eigen::VectorXd command = student.act(state, desired);  // line 9
        double update_seconds = seconds_since(start);
        const Eigen::VectorXd next = robot.step(command);
        // Line 10: D_i ← (x_{t+1}, x_t^d, τ_t) reformed as in (3).
        pending_states.push_back(state);
        pending_next.push_back(next);
        pending_commands.push_back(robot.command());
        const bool collided = robot.status().collision;
        if (static_cast<int>(pending_states.size()) == options.batch || collided ||
            t + 1 == length) {
          const auto retrain_start = std::chrono::steady_clock::now();
          for (std::size_t i = 0; i < pending_states.size(); ++i) {  // lines 11–12
            student.add(pending_states[i], pending_next[i], pending_commands[i]);
          }
          pending_states.clear();
          pending_next.clear();
          pending_commands.clear();
          update_seconds += seconds_since(retrain_start);
        }
        const Eigen::Vector3d reached = robot.task_point(next);
        squared_tracking += (reached - path.row(row).rightCols<3>().transpose()).squaredNorm();
        AdaptationStep logged;
        logged.trial = logged_trial;
        logged.step = t;
        logged.state = next;
        logged.command = robot.command();
        logged.reference = desired;
        logged.status = robot.status();
        logged.update_seconds = update_seconds;
        result.steps.push_back(std::move(logged));
        state = next;
        if (collided) break;
      }
      AdaptationTrial summary =
          summarize_trial(logged_trial, profile_name(radius), result.steps, first);
      summary.tracking_rms = std::sqrt(squared_tracking / summary.steps);
      summary.coach_end_distance = (robot.task_point(state) - path_end).norm();
      optimizer.tell(offset, summary.coach_end_distance +
                                 (summary.collision ? options.collision_penalty : 0.0));
      summary.search_seconds = student.fit_hyperparameters(rng);
      result.trials.push_back(summary);
      const bool local_flag =
          !summary.collision && summary.coach_end_distance <= options.local_flag;
      // G_f: this trial ended at the goal, whichever profile coached it.
      if (!summary.collision && summary.final_goal_distance <= robot.success_distance()) {
        result.goal_flag = true;
        result.trials_to_goal = trial;
        break;
      }
      if (local_flag && !last_profile) break;
    }
    if (trial >= options.max_trials) break;
  }
  if (!result.goal_flag) result.trials_to_goal = trial;
  return result;
}

}  // namespace tendril::adapt
