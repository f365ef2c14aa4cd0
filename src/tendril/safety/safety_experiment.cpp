#include "tendril/safety/safety_experiment.hpp"

#include <chrono>
#include <cmath>
#include <vector>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/algorithm_registry.hpp"
#include "tendril/rl/dqn/q_greedy_policy.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/rl/vec_env_factory.hpp"
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
                                    const std::filesystem::path& run_directory) {
  namespace fs = std::filesystem;
  if (fs::exists(run_directory) && !fs::is_empty(run_directory)) {
    throw Error("the run directory is not empty; nothing is overwritten", run_directory.string());
  }
  fs::create_directories(run_directory);
  write_new_file_atomically(run_directory / "config.yaml", experiment.task.config.dump() + "\n",
                            "config");
  const auto start = std::chrono::steady_clock::now();
  const rl::Experiment& task_experiment = experiment.task;
  auto env = rl::make_vec_env(task_experiment.env);
  auto task = rl::make_algorithm(task_experiment, *env);
  auto safety_agent = make_safety_agent(experiment.safety_algorithm, experiment.safety_algo, *env,
                                        task_experiment.seed + 1, "safety.algorithm");
  auto& off_policy = dynamic_cast<rl::OffPolicyAlgorithm&>(*safety_agent);
  auto single = envs::make(task_experiment.env.id, task_experiment.env.params);
  const auto constraint = constraint_of(*single);
  SafetyCoTrainer co_trainer(off_policy, *constraint, SafetyReward(experiment.safety_gamma),
                             experiment.co_training, task_experiment.n_timesteps,
                             task_experiment.seed + 2);
  task->learn(task_experiment.n_timesteps, rl::Observers{&co_trainer});
  task->policy().save(run_directory / "model.policy");
  critic_of(experiment.safety_algorithm, *safety_agent)->save(run_directory / "safety.critic");

  SafetyTrainResult result;
  result.run_directory = run_directory;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.stored_transitions = co_trainer.stored_transitions();
  result.gated_transitions = co_trainer.gated_transitions();
  result.unsafe_entries = co_trainer.unsafe_entries();
  return result;
}

SafetyEvaluation evaluate_safety(Env& env, const Constraint& constraint, const TaskActor& actor,
                                 int episodes, uint64_t seed) {
  require(episodes >= 1, "at least one episode", "evaluate_safety");
  std::vector<double> returns;
  int safe = 0;
  for (int i = 0; i < episodes; ++i) {
    Observation observation = env.reset(seed + static_cast<uint64_t>(i));
    bool violated = constraint.unsafe(observation);
    double total = 0.0;
    for (;;) {
      const Step step = env.step(actor(observation));
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

RunSafetyEvaluation evaluate_safety_run(const std::filesystem::path& run_directory, double epsilon,
                                        int episodes, uint64_t seed) {
  const bool has_critic = std::filesystem::exists(run_directory / "safety.critic");
  const rl::Experiment task =
      has_critic
          ? SafetyExperiment::from_config(Config::load_file(run_directory / "config.yaml")).task
          : rl::load_run_experiment(run_directory);
  require(!task.env.normalize_observation,
          "safety is judged on raw observations: the run normalizes them", run_directory.string());
  const auto policy = rl::load_policy(run_directory / "model.policy");
  Config params = task.env.params;
  if (params.has("unsafe_penalty")) params.set("unsafe_penalty", "0");
  auto env = envs::make(task.env.id, params);
  const auto constraint = constraint_of(*env);

  RunSafetyEvaluation result;
  result.epsilon = epsilon;
  Rng task_rng(seed);
  result.unfiltered = evaluate_safety(
      *env, *constraint, policy_actor(*policy, task.eval_deterministic, task_rng), episodes, seed);
  if (!has_critic) return result;
  const auto critic = load_safety_critic(run_directory / "safety.critic");
  Rng filtered_rng(seed);
  SafetyFilter filter(policy_actor(*policy, task.eval_deterministic, filtered_rng), *critic,
                      epsilon);
  result.filtered = evaluate_safety(
      *env, *constraint, [&filter](const Observation& x) { return filter.act(x); }, episodes, seed);
  result.filtered->intervention_rate = filter.intervention_rate();
  return result;
}

}  // namespace tendril::safety
