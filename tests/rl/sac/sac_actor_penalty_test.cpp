#include <gtest/gtest.h>

#include "tendril/rl/sac/actor_penalty.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

// The term ν · mean(a): its gradient ν/B per action pushes every action towards −1.
class PullDown : public ActorPenalty {
 public:
  explicit PullDown(float nu) : nu_(nu) {}
  double add_gradient(const Eigen::MatrixXf& /*observations*/, const Eigen::MatrixXf& actions,
                      Eigen::Ref<Eigen::MatrixXf> action_gradient) override {
    ++calls;
    action_gradient.array() += nu_ / static_cast<float>(actions.cols());
    return nu_ * static_cast<double>(actions.mean());
  }
  int calls = 0;

 private:
  float nu_;
};

// SAC on IdentityBox (reward 1 for a ≈ s) learns a ≈ s; with a penalty that outweighs that
// reward installed, the same run's actor is pulled to the lower bound instead.
float mean_action_at_half(ActorPenalty* penalty) {
  VecEnvOptions options;
  options.id = "IdentityBox-v0";
  auto env = make_vec_env(options);
  Sac sac(*env,
          SacConfig::from_config(Config::parse(
              "net_arch: [32, 32]\nlearning_starts: 200\nbatch_size: 64\nlearning_rate: 3.0e-3")),
          7);
  sac.set_actor_penalty(penalty);
  sac.learn(1500);
  Rng rng(0);
  return sac.policy().act(Observation::Constant(1, 0.5f), /*deterministic=*/true, rng)[0];
}

TEST(SacActorPenalty, AddsItsGradientToTheActorsObjective) {
  PullDown pull(20.0f);
  const float free = mean_action_at_half(nullptr);
  const float pulled = mean_action_at_half(&pull);
  EXPECT_GT(pull.calls, 1000);  // once per actor step
  EXPECT_NEAR(free, 0.5f, 0.25f);
  EXPECT_LT(pulled, -0.8f);
}

}  // namespace
}  // namespace tendril::rl
