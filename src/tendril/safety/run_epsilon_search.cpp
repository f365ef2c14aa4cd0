#include "tendril/safety/run_epsilon_search.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/safety/constraint.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_evaluation.hpp"
#include "tendril/safety/search_space.hpp"

namespace tendril::safety {

RunEpsilonSearch search_epsilon_of_run(const std::filesystem::path& run_directory,
                                       const EpsilonSearchOptions& options, uint64_t seed,
                                       double gradient_step) {
  require(gradient_step > 0.0, "the gradient's difference step must be positive",
          "search_epsilon_of_run");
  const rl::Experiment run = task_experiment_of_run(run_directory);
  const auto critic = load_safety_critic(run_directory / "safety.critic");
  auto env = envs::make(run.env.id, run.env.params);
  const auto constraint = constraint_of(*env);
  const auto space = search_space_of(*env);
  env->reset(seed);

  EpsilonSearchProblem problem;
  problem.value = [&](const Eigen::VectorXd& s) {
    return critic->state_value(space->observation(s));
  };
  problem.gradient = [&](const Eigen::VectorXd& s) {
    return finite_difference_gradient(problem.value, s, gradient_step);
  };
  problem.max_episode_length = constraint->horizon();
  problem.episode_length = [&](const Eigen::VectorXd& s) -> int64_t {
    env->reset();
    space->place(*env, s);
    Observation x = space->observation(s);
    if (constraint->unsafe(x)) return 0;
    for (int64_t t = 0; t < problem.max_episode_length; ++t) {
      const Step step = env->step(critic->safe_action(x));
      x = step.observation;
      if (constraint->unsafe(x)) return t;
      if (step.terminated || step.truncated) break;
    }
    return problem.max_episode_length;
  };
  problem.sample_state = [&](Rng& rng) { return space->sample(rng); };

  Rng rng(seed);
  RunEpsilonSearch search;
  search.result = search_epsilon(problem, options, rng);
  search.state_names = space->names();
  search.state_scales = space->scales();
  return search;
}

}  // namespace tendril::safety
