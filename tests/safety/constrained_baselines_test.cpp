#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "support/learning_seed.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/safety/constrained_experiment.hpp"
#include "tendril/safety/safety_evaluation.hpp"

// Table 6.1's baselines (seed 001 §6.4) learn on a small case where the task conflicts with
// safety: the double integrator with its goal moved to x = 2.5 m, beyond the safe 2 m, so the
// unconstrained optimum is to sit in X_unsafe and every constrained optimum sits on the boundary.
// Starts near the origin at low speed are all recoverable.
//
// Each method trains with three seeds and the assertions hold on every seed where the method
// guarantees the property (the unconstrained policy is unsafe, Lagrangian relaxation is safe) and
// on the mean over the seeds where it is a tendency: RSPO anneals its
// multiplier to a permissive value, so its final policy hugs the boundary and a seed may end just
// beyond it (the thesis measures RSPO's safety rate at 0.855 ± 0.138 over 10 seeds); LR's
// multiplier keeps rising, so it buys safety with a return that varies by seed.
//
// Measured margins (seeds 0–2 plus TENDRIL_TEST_SEED_OFFSET 0…7, OpenBLAS kernels Cooperlake
// (native here), Haswell and Sandybridge): docs/testing.md.
namespace tendril::safety {
namespace {

constexpr int kSeeds = 3;

const char* kEnvParams =
    "{horizon: 50, goal_position: 2.5, start_position: 0.5, start_velocity: 0.5";

std::string task_config(const std::string& extra_env_params, uint64_t seed) {
  return std::string("algorithm: sac\nenv: {id: Safety/DoubleIntegrator-v0, params: ") +
         kEnvParams + extra_env_params +
         "}}\nalgo: {net_arch: [32, 32], learning_starts: 500, batch_size: 64, gamma: 0.95, "
         "buffer_size: 10000}\nn_timesteps: 15000\nseed: " +
         std::to_string(seed) + "\neval: {episodes: 2}\n";
}

std::string constrained_section(const std::string& method, const std::string& multiplier) {
  return "constrained:\n  method: " + method +
         "\n  cost_limit: 0.1\n  cost_critic: {gamma: 0.9, net_arch: [32, 32], "
         "learning_rate: 1.0e-3, tau: 0.005, buffer_size: 10000, batch_size: 64, "
         "learning_starts: 500}\n  multiplier: " +
         multiplier + "\n";
}

struct Outcome {
  SafetyEvaluation evaluation;  // the deterministic policy from 100 starts, no filter
  double final_multiplier = 0.0;
};

Outcome evaluated(const std::filesystem::path& run, double final_multiplier) {
  Outcome outcome{evaluate_safety_run(run, 0.0, 100, 0).unfiltered, final_multiplier};
  std::printf("%s: safety rate %.2f, return %.1f\n", run.filename().c_str(),
              outcome.evaluation.safety_rate, outcome.evaluation.mean_return);
  return outcome;
}

// The same training under kSeeds seeds, each in directory / "<name>_<seed>".
template <typename Train>
std::vector<Outcome> over_seeds(const std::filesystem::path& directory, const std::string& name,
                                const Train& train) {
  std::vector<Outcome> outcomes;
  for (int k = 0; k < kSeeds; ++k) {
    const uint64_t seed = testing::learning_seed(k);
    outcomes.push_back(train(directory / (name + "_" + std::to_string(seed)), seed));
  }
  return outcomes;
}

std::vector<Outcome> train_plain(const std::filesystem::path& directory, const std::string& name,
                                 const std::string& extra_env_params) {
  return over_seeds(directory, name, [&](const std::filesystem::path& run, uint64_t seed) {
    rl::TrainOptions quiet;
    quiet.quiet = true;
    rl::train(rl::Experiment::from_config(Config::parse(task_config(extra_env_params, seed))), run,
              quiet);
    return evaluated(run, 0.0);
  });
}

std::vector<Outcome> train_with_constraint(const std::filesystem::path& directory,
                                           const std::string& method,
                                           const std::string& multiplier) {
  return over_seeds(directory, method, [&](const std::filesystem::path& run, uint64_t seed) {
    const Config config =
        Config::parse(task_config("", seed) + constrained_section(method, multiplier));
    rl::TrainOptions quiet;
    quiet.quiet = true;
    const rl::TrainResult trained =
        train_constrained(ConstrainedExperiment::from_config(config), run, quiet);
    double multiplier = std::nan("");
    for (const auto& [name, value] : trained.companion_scalars) {
      if (name == "lagrangian/multiplier") multiplier = value;
    }
    return evaluated(run, multiplier);
  });
}

double mean_return(const std::vector<Outcome>& outcomes) {
  double sum = 0.0;
  for (const Outcome& o : outcomes) sum += o.evaluation.mean_return;
  return sum / static_cast<double>(outcomes.size());
}

double mean_safety_rate(const std::vector<Outcome>& outcomes) {
  double sum = 0.0;
  for (const Outcome& o : outcomes) sum += o.evaluation.safety_rate;
  return sum / static_cast<double>(outcomes.size());
}

double lowest_safety_rate(const std::vector<Outcome>& outcomes) {
  double lowest = 1.0;
  for (const Outcome& o : outcomes) lowest = std::min(lowest, o.evaluation.safety_rate);
  return lowest;
}

double highest_safety_rate(const std::vector<Outcome>& outcomes) {
  double highest = 0.0;
  for (const Outcome& o : outcomes) highest = std::max(highest, o.evaluation.safety_rate);
  return highest;
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

  // Unconstrained SAC goes for the goal: unsafe in every seed, far better than standing still.
  const auto unconstrained = train_plain(directory_, "unconstrained", "");
  EXPECT_LE(highest_safety_rate(unconstrained), 0.05);
  EXPECT_GT(mean_return(unconstrained), still + 40.0);

  // Reward penalty, −10 per step in X_unsafe (20× the most a step beyond 2 m gains): its
  // optimum is on the boundary too, so a seed may stop a hair beyond it from a few starts (0.90
  // at worst measured); safe on average, and it still learns the task.
  const auto penalty = train_plain(directory_, "penalty", ", unsafe_penalty: 10.0");
  EXPECT_GE(mean_safety_rate(penalty), 0.9);
  EXPECT_GT(mean_return(penalty), still + 25.0);

  // RSPO: the multiplier annealed from 100 to 20 over the budget. Strict early, permissive at
  // the end: it ends nearer the boundary than the penalty (a higher return) and safer than the
  // unconstrained policy on average.
  const auto rspo = train_with_constraint(directory_, "rspo", "{start: 100.0, end: 20.0}");
  for (const Outcome& o : rspo) EXPECT_DOUBLE_EQ(o.final_multiplier, 20.0);
  EXPECT_GT(mean_return(rspo), mean_return(penalty));
  EXPECT_GE(mean_safety_rate(rspo), 0.3);

  // Lagrangian relaxation: ν rises by dual ascent while the policy's risk on the replayed states
  // exceeds the cost limit, and the policy it shapes is safe in every seed. Its return is the
  // price: near standing still, never a collapse.
  const auto lagrangian =
      train_with_constraint(directory_, "lagrangian", "{initial: 10.0, learning_rate: 1.0e-3}");
  for (const Outcome& o : lagrangian) EXPECT_GT(o.final_multiplier, 100.0);
  EXPECT_GE(lowest_safety_rate(lagrangian), 0.95);
  EXPECT_GT(mean_return(lagrangian), still - 20.0);

  // Safety has a price: every constrained baseline returns less than the unconstrained policy.
  for (const auto* safe : {&penalty, &rspo, &lagrangian}) {
    EXPECT_LT(mean_return(*safe), mean_return(unconstrained));
  }
}

}  // namespace
}  // namespace tendril::safety
