#include "tendril/safety/safety_experiment.hpp"

#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/algorithm_registry.hpp"
#include "tendril/rl/dqn/dqn.hpp"
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

// The safety agent of `algorithm` on `env` (only SAC and DQN have a SafetyCritic), built with its
// type known, beside the two ways to read its critic: as it stands (a copy, for saving) and
// following its updates (the training filter's; DQN's policy is its network either way).
struct SafetyAgent {
  std::unique_ptr<rl::OffPolicyAlgorithm> algorithm;
  std::function<std::unique_ptr<SafetyCritic>()> critic, live_critic;
};

SafetyAgent make_safety_agent(const std::string& algorithm, const Config& algo, envs::VecEnv& env,
                              uint64_t seed, const std::string& where) {
  if (algorithm == "sac") {
    auto sac = std::make_unique<rl::Sac>(env, rl::SacConfig::from_config(algo), seed);
    const rl::Sac* agent = sac.get();
    return {
        std::move(sac),
        [agent] { return std::make_unique<SacSafetyCritic>(agent->policy(), agent->critics()); },
        [agent] { return std::make_unique<SacSafetyCritic>(*agent); }};
  }
  if (algorithm == "dqn") {
    auto dqn = std::make_unique<rl::Dqn>(env, rl::DqnConfig::from_config(algo), seed);
    const rl::Dqn* agent = dqn.get();
    auto critic = [agent] { return std::make_unique<DqnSafetyCritic>(agent->q_policy()); };
    return {std::move(dqn), critic, critic};
  }
  throw Error(
      "the safety agent is 'sac' (Box actions) or 'dqn' (Discrete), not '" + algorithm + "'",
      where);
}

// The safety agent's scalars of an iteration: its last update ("train/x" as "safety/x"), its
// buffer and, with a training filter, the share of the iteration's decisions it overrode.
class SafetyScalars {
 public:
  // Counts the filter's decisions from where they stand (zero, or a resumed run's).
  SafetyScalars(const SafetyCoTrainer& co_trainer, const FilteredVecEnv* filtered)
      : co_trainer_(co_trainer),
        filtered_(filtered),
        decisions_(filtered != nullptr ? filtered->decisions() : 0),
        interventions_(filtered != nullptr ? filtered->interventions() : 0) {}

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
  int64_t decisions_, interventions_;
};

// The co-trained safety agent as the companion of the task run. It builds, in the order the
// seeds above assume: the safety agent on the run's environments, then (with a training filter)
// the filter around them, then the co-trainer; the task agent is made on what `attach` returns.
class SafetyCoTraining : public rl::RunCompanion {
 public:
  explicit SafetyCoTraining(const SafetyExperiment& experiment)
      : experiment_(experiment), filter_rng_(experiment.task.seed + 3) {}

  std::string name() const override { return "safety co-training"; }

  std::unique_ptr<envs::VecEnv> attach(std::unique_ptr<envs::VecEnv> env) override {
    const rl::Experiment& task = experiment_.task;
    // The safety agent never steps the environments; it is built on them for their spaces.
    agent_ = make_safety_agent(experiment_.safety_algorithm, experiment_.safety_algo, *env,
                               task.seed + 1, "safety.algorithm");
    rl::OffPolicyAlgorithm& agent = *agent_.algorithm;
    single_ = envs::make(task.env.id, task.env.params);
    constraint_ = constraint_of(*single_);
    co_trainer_.emplace(agent, *constraint_, SafetyReward(experiment_.safety_gamma),
                        experiment_.co_training, task.n_timesteps, task.seed + 2);
    if (experiment_.training_filter) {
      live_critic_ = agent_.live_critic();
      auto wrapper = std::make_unique<FilteredVecEnv>(
          std::move(env), *live_critic_,
          [this](const Observation& x) {
            return agent_.algorithm->policy().act(x, /*deterministic=*/false, filter_rng_);
          },
          experiment_.training_filter_epsilon);
      filtered_ = wrapper.get();
      co_trainer_->learn_executed_actions_of(*filtered_);
      env = std::move(wrapper);
    }
    scalars_.emplace(*co_trainer_, filtered_);
    return env;
  }

  void on_step(const rl::StepEvent& event) override { co_trainer_->on_step(event); }
  void add_scalars(rl::TrainStats& stats) override { (*scalars_)(stats); }

  void save(ArchiveWriter& writer) const override {
    const std::string agent = agent_.algorithm->checkpoint_bytes();
    writer.put_bytes("safety/agent", std::as_bytes(std::span<const char>(agent)));
    co_trainer_->save(writer, "safety/co_trainer/");
    writer.put_rng("safety/filter_rng", filter_rng_);
  }

  std::function<void()> load(const ArchiveReader& reader) override {
    const Snapshot agent = reader.get_bytes("safety/agent");
    // The agent's own checkpoint verifies and installs as a whole; should a later read fail,
    // the trainer loads an older checkpoint, which installs it again.
    agent_.algorithm->load_checkpoint_bytes(
        std::string(reinterpret_cast<const char*>(agent.data()), agent.size()),
        reader.name() + " (safety agent)");
    std::function<void()> install_co_trainer =
        co_trainer_->prepare_load(reader, "safety/co_trainer/");
    const Rng filter_rng = reader.get_rng("safety/filter_rng");
    return [this, install_co_trainer, filter_rng] {
      install_co_trainer();
      filter_rng_ = filter_rng;
      // The filter's counts come back with the environments' state; count from there.
      scalars_.emplace(*co_trainer_, filtered_);
    };
  }

  void finish(const std::filesystem::path& run_directory) const override {
    agent_.critic()->save(run_directory / "safety.critic");
  }

 private:
  const SafetyExperiment& experiment_;
  SafetyAgent agent_;
  std::unique_ptr<Env> single_;
  std::unique_ptr<envs::SafetyConstraint> constraint_;
  std::optional<SafetyCoTrainer> co_trainer_;
  std::unique_ptr<SafetyCritic> live_critic_;
  Rng filter_rng_;
  FilteredVecEnv* filtered_ = nullptr;  // owned by the run's vector env
  std::optional<SafetyScalars> scalars_;
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

rl::CompanionFactory co_trained_safety_agent(const SafetyExperiment& experiment) {
  return [&experiment] { return std::make_unique<SafetyCoTraining>(experiment); };
}

rl::TrainResult train_with_safety(const SafetyExperiment& experiment,
                                  const std::filesystem::path& run_directory,
                                  rl::TrainOptions options) {
  options.companion = co_trained_safety_agent(experiment);
  return rl::train(experiment.task, run_directory, options);
}

}  // namespace tendril::safety
