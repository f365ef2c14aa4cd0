#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/scratch_directory.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/safety/constrained_experiment.hpp"
#include "tendril/safety/safety_evaluation.hpp"

// Table 6.1's baselines (seed 001 §6.4) learn on a small case where the task conflicts with
// safety: the double integrator with its goal moved to x = 2.5 m, beyond the safe 2 m, so the
// unconstrained optimum is to sit in X_unsafe. Starts near the origin at low speed are all
// recoverable. Every run is seeded, so each outcome below is the same on every run of the test.
namespace tendril::safety {
namespace {

const char* kEnvParams =
    "{horizon: 50, goal_position: 2.5, start_position: 0.5, start_velocity: 0.5";

std::string task_config(const std::string& extra_env_params) {
  return std::string("algorithm: sac\nenv: {id: Safety/DoubleIntegrator-v0, params: ") +
         kEnvParams + extra_env_params +
         "}}\nalgo: {net_arch: [32, 32], learning_starts: 500, batch_size: 64, gamma: 0.95, "
         "buffer_size: 10000}\nn_timesteps: 15000\nseed: 0\neval: {episodes: 2}\n";
}

std::string constrained_section(const std::string& method, const std::string& multiplier) {
  return "constrained:\n  method: " + method +
         "\n  cost_limit: 0.1\n  cost_critic: {gamma: 0.9, net_arch: [32, 32], "
         "learning_rate: 1.0e-3, tau: 0.005, buffer_size: 10000, batch_size: 64, "
         "learning_starts: 500}\n  multiplier: " +
         multiplier + "\n";
}

SafetyEvaluation evaluate(const std::filesystem::path& run) {
  return evaluate_safety_run(run, 0.0, 100, 0).unfiltered;
}

SafetyEvaluation train_plain(const std::filesystem::path& run,
                             const std::string& extra_env_params) {
  rl::TrainOptions quiet;
  quiet.quiet = true;
  rl::train(rl::Experiment::from_config(Config::parse(task_config(extra_env_params))), run, quiet);
  return evaluate(run);
}

struct ConstrainedOutcome {
  ConstrainedTrainResult trained;
  SafetyEvaluation evaluation;
};

ConstrainedOutcome train_with_constraint(const std::filesystem::path& run,
                                         const std::string& method, const std::string& multiplier) {
  const Config config = Config::parse(task_config("") + constrained_section(method, multiplier));
  ConstrainedOutcome outcome;
  outcome.trained = train_constrained(ConstrainedExperiment::from_config(config), run, true);
  outcome.evaluation = evaluate(run);
  return outcome;
}

// The return of standing still from the same 100 starts: what a policy that learned nothing but
// safety would get.
double standing_still_return() {
  auto env = envs::make("Safety/DoubleIntegrator-v0", Config::parse(std::string(kEnvParams) + "}"));
  return evaluate_safety(
             *env, *constraint_of(*env),
             [](const Observation&) { return Action::Constant(1, 0.0f); }, 100, 0)
      .mean_return;
}

class ConstrainedBaselines : public testing::ScratchDirectoryTest {
 protected:
  ConstrainedBaselines() : ScratchDirectoryTest("constrained_baselines") {}
};

TEST_F(ConstrainedBaselines, LearnToStayOutOfTheUnsafeSetWhereTheTaskLeadsIntoIt) {
  const double still = standing_still_return();

  const SafetyEvaluation unconstrained = train_plain(directory_ / "unconstrained", "");
  EXPECT_LE(unconstrained.safety_rate, 0.05);
  EXPECT_GT(unconstrained.mean_return, still + 40.0);

  // Reward penalty: −10 per step in X_unsafe.
  const SafetyEvaluation penalty = train_plain(directory_ / "penalty", ", unsafe_penalty: 10.0");
  EXPECT_GE(penalty.safety_rate, 0.95);
  EXPECT_GT(penalty.mean_return, still + 30.0);

  // RSPO: the multiplier annealed from 100 to 20 over the budget.
  const ConstrainedOutcome rspo =
      train_with_constraint(directory_ / "rspo", "rspo", "{start: 100.0, end: 20.0}");
  EXPECT_DOUBLE_EQ(rspo.trained.final_multiplier, 20.0);
  EXPECT_GE(rspo.evaluation.safety_rate, 0.95);
  EXPECT_GT(rspo.evaluation.mean_return, still + 30.0);

  // Lagrangian relaxation: ν rises by dual ascent while the policy's risk on the replayed states
  // exceeds the cost limit, and the policy it shapes stays safe.
  const ConstrainedOutcome lagrangian = train_with_constraint(
      directory_ / "lagrangian", "lagrangian", "{initial: 10.0, learning_rate: 1.0e-3}");
  EXPECT_GT(lagrangian.trained.final_multiplier, 100.0);
  EXPECT_GE(lagrangian.evaluation.safety_rate, 0.95);
  EXPECT_GT(lagrangian.evaluation.mean_return, still);

  // Safety has a price: every safe baseline returns less than the unconstrained policy.
  for (const double safe_return :
       {penalty.mean_return, rspo.evaluation.mean_return, lagrangian.evaluation.mean_return}) {
    EXPECT_LT(safe_return, unconstrained.mean_return);
  }
}

}  // namespace
}  // namespace tendril::safety
