#include "tendril/safety/safety_evaluation.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/safety/constrained_experiment.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_experiment.hpp"

namespace tendril::safety {

SafetyEvaluation evaluate_safety(Env& env, const Constraint& constraint, const TaskActor& actor,
                                 int episodes, uint64_t seed,
                                 std::vector<std::vector<double>>* trajectory) {
  require(episodes >= 1, "at least one episode", "evaluate_safety");
  std::vector<double> returns;
  int safe = 0;
  for (int i = 0; i < episodes; ++i) {
    Observation observation = env.reset(seed + static_cast<uint64_t>(i));
    bool violated = constraint.unsafe(observation);
    double total = 0.0;
    for (int64_t t = 0;; ++t) {
      const Action action = actor(observation);
      const Step step = env.step(action);
      if (trajectory != nullptr) {
        std::vector<double> row{static_cast<double>(i), static_cast<double>(t)};
        row.insert(row.end(), observation.data(), observation.data() + observation.size());
        row.insert(row.end(), action.data(), action.data() + action.size());
        row.push_back(constraint.unsafe(step.observation) ? 1.0 : 0.0);
        trajectory->push_back(std::move(row));
      }
      total += step.reward;
      observation = step.observation;
      violated = violated || constraint.unsafe(observation);
      if (step.terminated || step.truncated) break;
    }
    returns.push_back(total);
    if (!violated) ++safe;
  }
  SafetyEvaluation result;
  result.episodes = episodes;
  for (double r : returns) result.mean_return += r / episodes;
  for (double r : returns) {
    result.std_return += (r - result.mean_return) * (r - result.mean_return) / episodes;
  }
  result.std_return = std::sqrt(result.std_return);
  result.safety_rate = static_cast<double>(safe) / episodes;
  return result;
}

rl::Experiment task_experiment_of_config(const Config& config) {
  if (config.has("safety")) return SafetyExperiment::from_config(config).task;
  if (config.has("constrained")) return ConstrainedExperiment::from_config(config).task;
  return rl::Experiment::from_config(config);
}

rl::Experiment task_experiment_of_run(const std::filesystem::path& run_directory) {
  const std::filesystem::path file = run_directory / "config.yaml";
  require(std::filesystem::exists(file), "not a run directory (no config.yaml)",
          run_directory.string());
  const Config config = Config::load_file(file);
  if (config.has("safety") || config.has("constrained")) return task_experiment_of_config(config);
  return rl::load_run_experiment(run_directory);
}

RunSafetyEvaluation evaluate_safety_run(const std::filesystem::path& run_directory, double epsilon,
                                        int episodes, uint64_t seed, const TaskSource& source,
                                        std::vector<std::vector<double>>* trajectory) {
  const bool has_critic = std::filesystem::exists(run_directory / "safety.critic");
  const rl::Experiment run = task_experiment_of_run(run_directory);
  require(!run.env.normalize_observation,
          "safety is judged on raw observations: the run normalizes them", run_directory.string());
  Config params = run.env.params;
  if (params.has("unsafe_penalty")) params.set("unsafe_penalty", "0");
  if (params.has("start_anywhere")) params.set("start_anywhere", "false");
  auto env = envs::make(run.env.id, params);
  const auto constraint = constraint_of(*env);

  // The task actor, drawing from its own stream in each of the two evaluations.
  std::unique_ptr<rl::Policy> policy;
  bool deterministic = run.eval_deterministic;
  if (source.kind != TaskSource::Kind::kRandom) {
    const std::filesystem::path task_run =
        source.kind == TaskSource::Kind::kRun ? source.run : run_directory;
    if (source.kind == TaskSource::Kind::kRun) {
      const rl::Experiment other = task_experiment_of_run(task_run);
      require(other.env.id == run.env.id,
              "the task policy's run is on " + other.env.id + ", the critic's on " + run.env.id,
              task_run.string());
      deterministic = other.eval_deterministic;
    }
    policy = rl::load_policy(task_run / "model.policy");
  }
  const auto actor = [&](Rng& rng) {
    return policy ? policy_actor(*policy, deterministic, rng)
                  : random_actor(env->action_space(), rng);
  };

  RunSafetyEvaluation result;
  result.epsilon = epsilon;
  Rng task_rng(seed);
  result.unfiltered = evaluate_safety(*env, *constraint, actor(task_rng), episodes, seed,
                                      has_critic ? nullptr : trajectory);
  if (!has_critic) return result;
  const auto critic = load_safety_critic(run_directory / "safety.critic");
  Rng filtered_rng(seed);
  SafetyFilter filter(actor(filtered_rng), *critic, epsilon);
  result.filtered = evaluate_safety(
      *env, *constraint, [&filter](const Observation& x) { return filter.act(x); }, episodes, seed,
      trajectory);
  result.filtered->intervention_rate = filter.intervention_rate();
  return result;
}

}  // namespace tendril::safety
