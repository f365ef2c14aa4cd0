#include "tendril/safety/safety_evaluation.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/core/run_record.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/runner/policy_runner.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/safety/constrained_experiment.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_experiment.hpp"

namespace tendril::safety {

namespace {

// A task actor as a policy the runner can run: it draws from its own stream (the actor's), not
// the runner's, so an evaluation's actions do not depend on what else drew before it.
class ActorPolicy final : public Policy {
 public:
  ActorPolicy(const TaskActor& actor, const Env& env) : actor_(actor), env_(env) {}
  const Space& observation_space() const override { return env_.observation_space(); }
  const Space& action_space() const override { return env_.action_space(); }
  Action act(const Observation& observation, bool /*deterministic*/, Rng& /*rng*/) const override {
    return actor_(observation);
  }

 private:
  const TaskActor& actor_;
  const Env& env_;
};

// Whether each episode left the safe set (its first observation included), and the rows of the
// trajectory when asked for.
class SafetyObserver final : public envs::RunObserver {
 public:
  SafetyObserver(const envs::SafetyConstraint& constraint,
                 std::vector<std::vector<double>>* trajectory)
      : constraint_(constraint), trajectory_(trajectory) {}

  void on_episode_start(int64_t /*episode*/, uint64_t /*seed*/, const Observation& observation,
                        const Env& /*env*/) override {
    violated_ = constraint_.unsafe(observation);
  }
  void on_step(const envs::StepView& step) override {
    const bool unsafe = constraint_.unsafe(step.result.observation);
    if (trajectory_ != nullptr) {
      std::vector<double> row{static_cast<double>(step.episode), static_cast<double>(step.step)};
      row.insert(row.end(), step.observation.data(),
                 step.observation.data() + step.observation.size());
      row.insert(row.end(), step.action.data(), step.action.data() + step.action.size());
      row.push_back(unsafe ? 1.0 : 0.0);
      trajectory_->push_back(std::move(row));
    }
    violated_ = violated_ || unsafe;
  }
  void on_episode_end(const envs::EpisodeOutcome& /*outcome*/) override {
    if (!violated_) ++safe_;
  }
  int safe() const { return safe_; }

 private:
  const envs::SafetyConstraint& constraint_;
  std::vector<std::vector<double>>* trajectory_;
  bool violated_ = false;
  int safe_ = 0;
};

}  // namespace

SafetyEvaluation evaluate_safety(Env& env, const envs::SafetyConstraint& constraint,
                                 const TaskActor& actor, int episodes, uint64_t seed,
                                 std::vector<std::vector<double>>* trajectory) {
  require(episodes >= 1, "at least one episode", "evaluate_safety");
  SafetyObserver observer(constraint, trajectory);
  envs::RunSettings settings;
  settings.episodes = episodes;
  settings.seed = seed;
  const envs::RunResult run = envs::run_policy(ActorPolicy(actor, env), env, settings, {&observer});
  SafetyEvaluation result;
  result.episodes = episodes;
  for (const envs::EpisodeOutcome& e : run.episodes)
    result.mean_return += e.episode_return / episodes;
  for (const envs::EpisodeOutcome& e : run.episodes) {
    const double deviation = e.episode_return - result.mean_return;
    result.std_return += deviation * deviation / episodes;
  }
  result.std_return = std::sqrt(result.std_return);
  result.safety_rate = static_cast<double>(observer.safe()) / episodes;
  return result;
}

rl::Experiment task_experiment_of_config(const Config& config) {
  if (config.has("safety")) return SafetyExperiment::from_config(config).task;
  if (config.has("constrained")) return ConstrainedExperiment::from_config(config).task;
  return rl::Experiment::from_config(config);
}

rl::Experiment task_experiment_of_run(const std::filesystem::path& run_directory) {
  const Config config = load_run_config(run_directory);
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
