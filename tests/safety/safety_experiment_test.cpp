#include "tendril/safety/safety_experiment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "support/learning_seed.hpp"
#include "support/same_run.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_evaluation.hpp"

namespace tendril::safety {
namespace {

// DQN task agent and DQN safety agent on the discrete double integrator, small and fast.
const char* kExperiment = R"(
algorithm: dqn
env: {id: Safety/DoubleIntegrator-v0, params: {discrete_actions: 5, horizon: 100}}
algo: {net_arch: [32, 32], learning_starts: 200, batch_size: 32, gamma: 0.9,
       target_update_interval: 100, buffer_size: 5000, exploration_fraction: 0.5}
n_timesteps: 10000
seed: 3
safety:
  algorithm: dqn
  algo: {net_arch: [32, 32], learning_starts: 0, batch_size: 32, gamma: 0.9,
         target_update_interval: 100, buffer_size: 1000}
  learning_starts: 200
  eval: {episodes: 20, epsilon: 0.0}
)";

std::filesystem::path fresh_directory(const std::string& name) {
  const auto directory =
      std::filesystem::temp_directory_path() / "tendril_safety_experiment" / name;
  std::filesystem::remove_all(directory);
  return directory;
}

TEST(SafetyExperiment, ReadsTheSafetySectionAndRefusesBadKeys) {
  Config experiment = Config::parse(kExperiment);
  experiment.set("seed", std::to_string(testing::learning_seed(3)));
  const SafetyExperiment e = SafetyExperiment::from_config(experiment);
  EXPECT_EQ(e.safety_algorithm, "dqn");
  EXPECT_DOUBLE_EQ(e.safety_gamma, 0.9);
  EXPECT_EQ(e.co_training.learning_starts, 200);
  EXPECT_EQ(e.eval_episodes, 20);
  EXPECT_EQ(e.task.n_timesteps, 10000);

  Config unknown = Config::parse(kExperiment);
  unknown.set("safety.learning_start", "5");
  EXPECT_THROW(SafetyExperiment::from_config(unknown), Error);
  Config td3 = Config::parse(kExperiment);
  td3.set("safety.algorithm", "td3");
  EXPECT_THROW(SafetyExperiment::from_config(td3), Error);
  Config normalized = Config::parse(kExperiment);
  normalized.set("env.normalize_observation", "true");
  EXPECT_THROW(SafetyExperiment::from_config(normalized), Error);
  const Config no_constraint = Config::parse(
      "algorithm: dqn\nenv: {id: CartPole-v1}\nn_timesteps: 100\nsafety: {algorithm: dqn}");
  try {
    SafetyExperiment::from_config(no_constraint);
    FAIL() << "an environment without a constraint was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("no safety constraint"), std::string::npos)
        << error.what();
  }
}

// The shipped experiments of configs/safety/ read, with their safety sections.
TEST(SafetyExperiment, ShippedConfigsAreValid) {
  for (const char* name :
       {"double_integrator_sac.yaml", "dubins_dqn.yaml", "dubins_dqn_speed.yaml"}) {
    const SafetyExperiment e = SafetyExperiment::from_config(
        Config::load_file(std::string(TENDRIL_CONFIG_DIR) + "/safety/" + name));
    EXPECT_EQ(e.safety_algorithm, e.task.algorithm) << name;
    EXPECT_DOUBLE_EQ(e.safety_gamma, 0.99) << name;
  }
}

// Scripted actors with hand-computable outcomes: standing still at rest keeps every episode
// safe with return −T·|x₀ − 1.8|; full acceleration to the right leaves the safe set.
TEST(SafetyEvaluation, SafetyRateAndReturnOfScriptedActors) {
  const Config params = Config::parse("horizon: 50\nstart_velocity: 0.0\nstart_position: 1.0");
  auto env = envs::make("Safety/DoubleIntegrator-v0", params);
  const auto constraint = constraint_of(*env);
  double expected = 0.0;
  for (uint64_t i = 0; i < 8; ++i) {
    const Observation start = env->reset(100 + i);
    expected += -50.0 * std::abs(static_cast<double>(start[0]) - 1.8) / 8.0;
  }
  const SafetyEvaluation still = evaluate_safety(
      *env, *constraint, [](const Observation&) { return Action::Constant(1, 0.0f); }, 8, 100);
  EXPECT_EQ(still.episodes, 8);
  EXPECT_DOUBLE_EQ(still.safety_rate, 1.0);
  EXPECT_NEAR(still.mean_return, expected, 1e-4);
  const SafetyEvaluation rush = evaluate_safety(
      *env, *constraint, [](const Observation&) { return Action::Constant(1, 2.0f); }, 8, 100);
  EXPECT_DOUBLE_EQ(rush.safety_rate, 0.0);
}

// Train → files → evaluation: a filter that never intervenes (ε₂ far below every value)
// reproduces the task policy's episodes exactly, one that always intervenes acts only through
// the safety agent; the run refuses to overwrite a directory that holds files.
TEST(SafetyExperiment, TrainsWritesTheCriticAndEvaluatesWithAndWithoutTheFilter) {
  Config experiment = Config::parse(kExperiment);
  experiment.set("seed", std::to_string(testing::learning_seed(3)));
  const SafetyExperiment e = SafetyExperiment::from_config(experiment);
  const auto run = fresh_directory("dqn");
  rl::TrainOptions quiet;
  quiet.quiet = true;
  const rl::TrainResult trained = train_with_safety(e, run, quiet);
  ASSERT_TRUE(trained.finished);
  double stored = 0.0;
  for (const auto& [name, value] : trained.companion_scalars) {
    if (name == "safety/stored_transitions") stored = value;
  }
  EXPECT_GT(stored, 0.0);
  EXPECT_TRUE(std::filesystem::exists(run / "model.policy"));
  const auto critic = load_safety_critic(run / "safety.critic");
  // The co-trained critic separates a state deep inside the safe set from a doomed one.
  std::printf("safety value inside %.3f, doomed %.3f\n",
              critic->state_value(Eigen::Vector3f(0.0f, 0.0f, 0.0f)),
              critic->state_value(Eigen::Vector3f(1.9f, 2.8f, 0.0f)));
  EXPECT_GT(critic->state_value(Eigen::Vector3f(0.0f, 0.0f, 0.0f)), 0.0);
  EXPECT_LT(critic->state_value(Eigen::Vector3f(1.9f, 2.8f, 0.0f)), 0.0);

  const RunSafetyEvaluation never = evaluate_safety_run(run, -1e9, 10, 7);
  ASSERT_TRUE(never.filtered);
  EXPECT_DOUBLE_EQ(never.filtered->intervention_rate, 0.0);
  EXPECT_EQ(never.filtered->mean_return, never.unfiltered.mean_return);
  EXPECT_EQ(never.filtered->safety_rate, never.unfiltered.safety_rate);
  const RunSafetyEvaluation always = evaluate_safety_run(run, 1e9, 10, 7);
  ASSERT_TRUE(always.filtered);
  EXPECT_DOUBLE_EQ(always.filtered->intervention_rate, 1.0);
  EXPECT_EQ(always.unfiltered.mean_return, never.unfiltered.mean_return);

  EXPECT_THROW(train_with_safety(e, run), Error);
  EXPECT_TRUE(std::filesystem::exists(run / "safety.critic"));
}

// A co-training run with the training filter, stopped by SIGINT, resumed, paused and resumed
// again, ends with the files of the run that was never stopped: the task policy, the safety critic,
// the evaluations and every logged scalar (the filter's counts and draws, the gated buffer, the
// safety agent's weights, optimizer and streams travel in the checkpoint).
TEST(SafetyExperiment, AnInterruptedCoTrainingResumesToTheUninterruptedRunsFiles) {
  Config experiment = Config::parse(R"(
algorithm: sac
env: {id: Safety/DoubleIntegrator-v0, params: {horizon: 100, dt: 0.05}}
algo: {net_arch: [16, 16], learning_starts: 100, batch_size: 32, log_interval: 300}
n_timesteps: 1200
seed: 5
checkpoint_freq: 300
save_replay_buffer: true
safety:
  algorithm: sac
  algo: {net_arch: [16, 16], learning_starts: 0, batch_size: 32, buffer_size: 100}
  buffer_size: 2000
  learning_starts: 100
  training_filter: {enabled: true, epsilon: -5.0}
  eval: {episodes: 5}
)");
  const SafetyExperiment e = SafetyExperiment::from_config(experiment);
  rl::TrainOptions quiet;
  quiet.quiet = true;
  const auto whole = fresh_directory("whole");
  ASSERT_TRUE(train_with_safety(e, whole, quiet).finished);

  const auto stopped = fresh_directory("stopped");
  request_interrupt(SIGINT);  // seen at the end of the first iteration, 300 steps
  const rl::TrainResult first = train_with_safety(e, stopped, quiet);
  clear_interrupt();
  EXPECT_FALSE(first.finished);
  EXPECT_EQ(first.interrupted, SIGINT);
  EXPECT_EQ(rl::latest_checkpoint(stopped).filename(), "step_300.ckpt");
  EXPECT_FALSE(std::filesystem::exists(stopped / "safety.critic"));
  // Paused again at 900 steps, after the filter has drawn safe actions (from 600 on), then
  // resumed to the end.
  rl::TrainOptions resumed = quiet;
  resumed.companion = co_trained_safety_agent(e);
  resumed.stop_at = 900;
  EXPECT_EQ(rl::resume(stopped, e.task, resumed).timesteps, 900);
  resumed.stop_at.reset();
  ASSERT_TRUE(rl::resume(stopped, e.task, resumed).finished);
  testing::expect_same_run(stopped, whole, {"model.policy", "safety.critic", "eval.csv"});
  double interventions_before_pause = 0.0;
  for (const auto& [key, value] : testing::event_scalars(whole)) {
    if (key.first == "safety/intervention_rate" && key.second <= 900) {
      interventions_before_pause += value;
    }
  }
  EXPECT_GT(interventions_before_pause, 0.0);
}

// The reward-penalty baseline is a plain run (no safety agent): evaluated unfiltered, with the
// returns of the task reward alone (the penalty switched off), on the same episodes as the
// same policy would be without it.
TEST(SafetyExperiment, PlainRunsAreEvaluatedUnfilteredWithoutThePenalty) {
  const Config config = Config::parse(
      "algorithm: dqn\nenv: {id: Safety/DoubleIntegrator-v0, params: {discrete_actions: 3, "
      "horizon: 50, unsafe_penalty: 100.0}}\nalgo: {net_arch: [8], learning_starts: 100}\n"
      "n_timesteps: 500\nseed: 1\neval: {episodes: 2}");
  const auto run = fresh_directory("plain");
  rl::TrainOptions quiet;
  quiet.quiet = true;
  rl::train(rl::Experiment::from_config(config), run, quiet);
  const RunSafetyEvaluation result = evaluate_safety_run(run, 0.0, 20, 11);
  EXPECT_FALSE(result.filtered);
  const auto policy = rl::load_policy(run / "model.policy");
  auto env =
      envs::make("Safety/DoubleIntegrator-v0", Config::parse("discrete_actions: 3\nhorizon: 50"));
  Rng rng(11);
  const SafetyEvaluation expected =
      evaluate_safety(*env, *constraint_of(*env), policy_actor(*policy, true, rng), 20, 11);
  ASSERT_LT(expected.safety_rate, 1.0);  // some episode is penalized, so the penalty would show
  EXPECT_EQ(result.unfiltered.mean_return, expected.mean_return);
  EXPECT_EQ(result.unfiltered.safety_rate, expected.safety_rate);
}

}  // namespace
}  // namespace tendril::safety
