// SAC's delayed actor update (policy_delay) and gradient-norm clipping (max_grad_norm).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/error_message.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/sac/squashed_gaussian_policy.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

using tendril::testing::error_message;

constexpr int64_t kLearningStarts = 200;

// Exposes single calls of the update.
class SteppedSac : public Sac {
 public:
  using Sac::Sac;
  TrainStats update(int64_t gradient_steps) { return train(gradient_steps, 1.0); }
  const Eigen::VectorXf& actor() const {
    return dynamic_cast<const SquashedGaussianPolicy&>(policy()).parameters();
  }
};

struct Agent {
  std::unique_ptr<envs::VecEnv> env;
  std::unique_ptr<SteppedSac> sac;
};

// A SAC whose replay buffer holds kLearningStarts random transitions of Pendulum, not yet
// updated.
Agent warmed_up(const std::string& extra, uint64_t seed = 3) {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  Agent setup{make_vec_env(options), nullptr};
  const Config algo = Config::parse("learning_starts: " + std::to_string(kLearningStarts) +
                                    "\nbatch_size: 32\nnet_arch: [16, 16]\n" + extra);
  setup.sac = std::make_unique<SteppedSac>(*setup.env, SacConfig::from_config(algo), seed);
  setup.sac->learn(kLearningStarts);
  EXPECT_EQ(setup.sac->gradient_updates(), 0);
  return setup;
}

bool has(const TrainStats& stats, const std::string& name) {
  for (const auto& [key, value] : stats) {
    if (key == name) return true;
  }
  return false;
}

TEST(SacOptions, ConfigKeysAndDefaults) {
  const SacConfig defaults = SacConfig::from_config(Config::parse("{}"));
  EXPECT_EQ(defaults.policy_delay, 1);
  EXPECT_FALSE(defaults.max_grad_norm.has_value());
  const SacConfig set = SacConfig::from_config(Config::parse("policy_delay: 2\nmax_grad_norm: 1"));
  EXPECT_EQ(set.policy_delay, 2);
  EXPECT_EQ(set.max_grad_norm, 1.0);
  EXPECT_FALSE(SacConfig::from_config(Config::parse("max_grad_norm: none")).max_grad_norm);
  EXPECT_FALSE(defaults.compensate_policy_delay);
  const auto refused = [](const std::string& yaml) {
    return error_message([&] { SacConfig::from_config(Config::parse(yaml)); });
  };
  EXPECT_NE(refused("policy_delay: 0").find("policy_delay"), std::string::npos);
  EXPECT_NE(refused("max_grad_norm: -1").find("max_grad_norm"), std::string::npos);
  EXPECT_NE(refused("max_grad_norm: yes").find("max_grad_norm"), std::string::npos);
}

TEST(SacOptions, TheActorAndAlphaStepEveryThirdCriticStep) {
  Agent setup = warmed_up("policy_delay: 3\n");
  SteppedSac& sac = *setup.sac;
  const Eigen::VectorXf actor = sac.actor();
  const double alpha = sac.entropy_coefficient();
  for (int step = 1; step <= 2; ++step) {
    const Eigen::VectorXf critics = sac.critics().parameters();
    const TrainStats stats = sac.update(1);
    EXPECT_NE(sac.critics().parameters(), critics) << step;
    EXPECT_EQ(sac.actor(), actor) << step;
    EXPECT_EQ(sac.entropy_coefficient(), alpha) << step;
    EXPECT_FALSE(has(stats, "train/actor_loss")) << step;
    EXPECT_TRUE(has(stats, "train/critic_loss")) << step;
  }
  const TrainStats third = sac.update(1);
  EXPECT_NE(sac.actor(), actor);
  EXPECT_NE(sac.entropy_coefficient(), alpha);
  EXPECT_TRUE(has(third, "train/actor_loss"));
  EXPECT_TRUE(has(third, "train/ent_coef_loss"));
  EXPECT_EQ(sac.gradient_updates(), 3);
}

TEST(SacOptions, WithoutDelayTheActorStepsEveryTime) {
  Agent setup = warmed_up("");
  Eigen::VectorXf actor = setup.sac->actor();
  for (int step = 0; step < 3; ++step) {
    EXPECT_TRUE(has(setup.sac->update(1), "train/actor_loss"));
    EXPECT_NE(setup.sac->actor(), actor) << step;
    actor = setup.sac->actor();
  }
}

TEST(SacOptions, CompensationMakesUpTheSkippedActorAndAlphaSteps) {
  // One Adam step moves each parameter by at most lr = 3e-4 (|m̂| ≤ √v̂ on the first step); the
  // two steps of the delayed update move log α, whose gradient keeps its sign, by about 2 lr.
  const double lr = 3e-4;
  for (const bool compensate : {false, true}) {
    Agent agent = warmed_up("policy_delay: 2\ncompensate_policy_delay: " +
                            std::string(compensate ? "true" : "false") + "\n");
    SteppedSac& sac = *agent.sac;
    const Eigen::VectorXf actor = sac.actor();
    const double alpha = sac.entropy_coefficient();
    sac.update(1);
    EXPECT_EQ(sac.actor(), actor);
    EXPECT_TRUE(has(sac.update(1), "train/actor_loss"));
    const double actor_change = (sac.actor() - actor).cwiseAbs().maxCoeff();
    const double alpha_change = std::abs(std::log(sac.entropy_coefficient() / alpha));
    if (compensate) {
      EXPECT_GT(actor_change, 1.5 * lr);
      EXPECT_GT(alpha_change, 1.9 * lr);
    } else {
      EXPECT_LE(actor_change, 1.0001 * lr);
      EXPECT_LE(alpha_change, 1.0001 * lr);
      EXPECT_GT(alpha_change, 0.9 * lr);
    }
  }
}

// The largest change of any parameter in one update.
struct Changes {
  double actor, critics, log_alpha;
};

Changes one_update(const std::string& extra) {
  Agent setup = warmed_up(extra);
  const Eigen::VectorXf actor = setup.sac->actor(), critics = setup.sac->critics().parameters();
  const double alpha = setup.sac->entropy_coefficient();
  setup.sac->update(1);
  return {(setup.sac->actor() - actor).cwiseAbs().maxCoeff(),
          (setup.sac->critics().parameters() - critics).cwiseAbs().maxCoeff(),
          std::abs(std::log(setup.sac->entropy_coefficient() / alpha))};
}

TEST(SacOptions, ClippingShrinksTheGradientsOfActorCriticsAndAlpha) {
  // Adam's first step is lr · g / (|g| + 1e-8) per component: ≈ lr = 3e-4 for unclipped
  // gradients, but at most lr · 1e-4 once the whole gradient is clipped to norm 1e-12.
  const Changes unclipped = one_update("");
  const Changes clipped = one_update("max_grad_norm: 1.0e-12\n");
  const double lr = 3e-4;
  EXPECT_GT(unclipped.actor, 0.5 * lr);
  EXPECT_GT(unclipped.critics, 0.5 * lr);
  EXPECT_GT(unclipped.log_alpha, 0.5 * lr);
  EXPECT_LT(clipped.actor, 2e-4 * lr);
  EXPECT_LT(clipped.critics, 2e-4 * lr);
  EXPECT_LT(clipped.log_alpha, 2e-4 * lr);
}

TEST(SacOptions, AClipAboveEveryNormChangesNothing) {
  Agent unclipped = warmed_up(""), loose = warmed_up("max_grad_norm: 1.0e30\n");
  unclipped.sac->update(50);
  loose.sac->update(50);
  EXPECT_EQ(unclipped.sac->actor(), loose.sac->actor());
  EXPECT_EQ(unclipped.sac->critics().parameters(), loose.sac->critics().parameters());
  EXPECT_EQ(unclipped.sac->entropy_coefficient(), loose.sac->entropy_coefficient());
}

}  // namespace
}  // namespace tendril::rl
