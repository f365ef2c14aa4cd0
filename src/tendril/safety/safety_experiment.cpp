#include "tendril/safety/safety_experiment.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/algorithm_registry.hpp"
#include "tendril/rl/dqn/q_greedy_policy.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/rl/vec_env_factory.hpp"
#include "tendril/safety/run_files.hpp"
#include "tendril/safety/safety_critic.hpp"

namespace tendril::safety {
namespace {

std::string key(const Config& config, const std::string& name) {
  return config.source() + ": " + (config.path().empty() ? name : config.path() + "." + name);
}

// The safety agent of `algorithm` on `env`; only SAC and DQN have a SafetyCritic.
std::unique_ptr<rl::Algorithm> make_safety_agent(const std::string& algorithm, const Config& algo,
                                                 envs::VecEnv& env, uint64_t seed,
                                                 const std::string& where) {
  require(algorithm == "sac" || algorithm == "dqn",
          "the safety agent is 'sac' (Box actions) or 'dqn' (Discrete), not '" + algorithm + "'",
          where);
  return rl::algorithm_spec(algorithm, where).factory(env, algo, seed);
}

std::unique_ptr<SafetyCritic> critic_of(const std::string& algorithm, const rl::Algorithm& agent) {
  if (algorithm == "sac") {
    const auto& sac = dynamic_cast<const rl::Sac&>(agent);
    return std::make_unique<SacSafetyCritic>(sac.policy(), sac.critics());
  }
  return std::make_unique<DqnSafetyCritic>(dynamic_cast<const rl::QGreedyPolicy&>(agent.policy()));
}

// The critic of an agent in training, following its updates (DQN's policy is its network).
std::unique_ptr<SafetyCritic> live_critic_of(const std::string& algorithm,
                                             const rl::Algorithm& agent) {
  if (algorithm == "sac") {
    return std::make_unique<SacSafetyCritic>(dynamic_cast<const rl::Sac&>(agent));
  }
  return critic_of(algorithm, agent);
}

// The safety agent's scalars of an iteration: its last update ("train/x" as "safety/x"), its
// buffer and, with a training filter, the share of the iteration's decisions it overrode.
class SafetyScalars {
 public:
  SafetyScalars(const SafetyCoTrainer& co_trainer, const FilteredVecEnv* filtered)
      : co_trainer_(co_trainer), filtered_(filtered) {}

  void operator()(rl::TrainStats& stats) {
    for (const auto& [name, value] : co_trainer_.last_stats()) {
      const std::string prefix = "train/";
      stats.emplace_back(
          "safety/" + (name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name), value);
    }
    stats.emplace_back("safety/stored_transitions",
                       static_cast<double>(co_trainer_.stored_transitions()));
    stats.emplace_back("safety/unsafe_entries", static_cast<double>(co_trainer_.unsafe_entries()));
    if (filtered_ == nullptr) return;
    const int64_t decisions = filtered_->decisions() - decisions_;
    const int64_t interventions = filtered_->interventions() - interventions_;
    decisions_ = filtered_->decisions();
    interventions_ = filtered_->interventions();
    if (decisions > 0) {
      stats.emplace_back("safety/intervention_rate",
                         static_cast<double>(interventions) / static_cast<double>(decisions));
    }
  }

 private:
  const SafetyCoTrainer& co_trainer_;
  const FilteredVecEnv* filtered_;
  int64_t decisions_ = 0, interventions_ = 0;
};

}  // namespace

SafetyExperiment SafetyExperiment::from_config(Config config) {
  SafetyExperiment e;
  // The safety section first: Experiment::from_config rejects keys nobody has read.
  const Config safety = config.child("safety");
  e.safety_algorithm = safety.get<std::string>("algorithm");
  e.safety_algo = safety.child("algo");
  e.co_training.buffer_size = safety.get_or<int64_t>("buffer_size", e.co_training.buffer_size);
  e.co_training.learning_starts =
      safety.get_or<int64_t>("learning_starts", e.co_training.learning_starts);
  e.co_training.train_freq = safety.get_or<int64_t>("train_freq", e.co_training.train_freq);
  e.co_training.gradient_steps =
      safety.get_or<int64_t>("gradient_steps", e.co_training.gradient_steps);
  e.co_training.unsafe_samples_per_step =
      safety.get_or<int64_t>("unsafe_samples_per_step", e.co_training.unsafe_samples_per_step);
  require(e.co_training.buffer_size >= 1, "must be at least 1", key(safety, "buffer_size"));
  require(e.co_training.learning_starts >= 0, "must be non-negative",
          key(safety, "learning_starts"));
  require(e.co_training.train_freq >= 1, "must be at least 1", key(safety, "train_freq"));
  require(e.co_training.gradient_steps >= 0, "must be non-negative", key(safety, "gradient_steps"));
  require(e.co_training.unsafe_samples_per_step >= 0, "must be non-negative",
          key(safety, "unsafe_samples_per_step"));
  const Config training_filter = safety.child("training_filter");
  e.training_filter = training_filter.get_or<bool>("enabled", e.training_filter);
  e.training_filter_epsilon = training_filter.get_or<double>("epsilon", e.training_filter_epsilon);
  require(std::isfinite(e.training_filter_epsilon), "must be finite",
          key(training_filter, "epsilon"));
  const Config eval = safety.child("eval");
  e.eval_episodes = eval.get_or<int>("episodes", e.eval_episodes);
  e.eval_epsilon = eval.get_or<double>("epsilon", e.eval_epsilon);
  e.eval_deterministic = eval.get_or<bool>("deterministic", e.eval_deterministic);
  require(e.eval_episodes >= 1, "must be at least 1", key(eval, "episodes"));
  require(std::isfinite(e.eval_epsilon), "must be finite", key(eval, "epsilon"));

  // Build the safety agent once on a probe of the environment (marks and checks its keys).
  const std::string where = key(safety, "algorithm");
  e.safety_gamma = rl::algorithm_spec(e.safety_algorithm, where).gamma(e.safety_algo);
  const Config env = config.child("env");
  rl::VecEnvOptions probe_options;
  probe_options.id = env.get<std::string>("id");
  probe_options.params = env.child("params");
  auto probe = rl::make_vec_env(probe_options);
  make_safety_agent(e.safety_algorithm, e.safety_algo, *probe, 0, where);

  e.task = rl::Experiment::from_config(config);
  require(!e.task.env.normalize_observation,
          "the safety agent learns on raw observations: normalize_observation must be false",
          key(env, "normalize_observation"));
  auto single = envs::make(e.task.env.id, e.task.env.params);
  constraint_of(*single);  // an environment without a constraint is refused here
  return e;
}

SafetyTrainResult train_with_safety(const SafetyExperiment& experiment,
                                    const std::filesystem::path& run_directory, bool quiet) {
  start_run_directory(run_directory, experiment.task.config);
  const auto start = std::chrono::steady_clock::now();
  const rl::Experiment& task_experiment = experiment.task;
  std::unique_ptr<envs::VecEnv> env = rl::make_vec_env(task_experiment.env);
  // The safety agent never steps the environments; it is built on them for their spaces.
  auto safety_agent = make_safety_agent(experiment.safety_algorithm, experiment.safety_algo, *env,
                                        task_experiment.seed + 1, "safety.algorithm");
  auto& off_policy = dynamic_cast<rl::OffPolicyAlgorithm&>(*safety_agent);
  std::unique_ptr<SafetyCritic> live_critic;
  FilteredVecEnv* filtered = nullptr;
  Rng filter_rng(task_experiment.seed + 3);
  if (experiment.training_filter) {
    live_critic = live_critic_of(experiment.safety_algorithm, *safety_agent);
    const rl::Policy& safety_policy = safety_agent->policy();
    auto wrapper = std::make_unique<FilteredVecEnv>(
        std::move(env), *live_critic,
        [&safety_policy, &filter_rng](const Observation& x) {
          return safety_policy.act(x, /*deterministic=*/false, filter_rng);
        },
        experiment.training_filter_epsilon);
    filtered = wrapper.get();
    env = std::move(wrapper);
  }
  auto task = rl::make_algorithm(task_experiment, *env);
  auto single = envs::make(task_experiment.env.id, task_experiment.env.params);
  const auto constraint = constraint_of(*single);
  SafetyCoTrainer co_trainer(off_policy, *constraint, SafetyReward(experiment.safety_gamma),
                             experiment.co_training, task_experiment.n_timesteps,
                             task_experiment.seed + 2);
  if (filtered != nullptr) co_trainer.learn_executed_actions_of(*filtered);
  RunScalarLog progress(run_directory, SafetyScalars(co_trainer, filtered));
  rl::ProgressLine progress_line(task_experiment.n_timesteps, 0);
  rl::Observers observers{&co_trainer, &progress};
  if (!quiet) observers.push_back(&progress_line);
  task->learn(task_experiment.n_timesteps, observers);
  if (!quiet) progress_line.finish();
  task->policy().save(run_directory / "model.policy");
  critic_of(experiment.safety_algorithm, *safety_agent)->save(run_directory / "safety.critic");

  SafetyTrainResult result;
  result.run_directory = run_directory;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.stored_transitions = co_trainer.stored_transitions();
  result.gated_transitions = co_trainer.gated_transitions();
  result.unsafe_entries = co_trainer.unsafe_entries();
  if (filtered != nullptr && filtered->decisions() > 0) {
    result.training_intervention_rate =
        static_cast<double>(filtered->interventions()) / static_cast<double>(filtered->decisions());
  }
  return result;
}

}  // namespace tendril::safety
