#include "tendril/rl/gae.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/rl/rollout_buffer.hpp"

namespace tendril::rl {
namespace {

// Two environments, five steps, γ = 0.9, λ = 0.5 (γλ = 0.45).
// Env 0: step 1 is truncated by a time limit (V(final obs) = 4), step 3 terminates.
// Env 1: one long episode that continues past the rollout (V(s_5) = 0).
GaeInput example() {
  GaeInput input;
  input.n_steps = 5;
  input.n_envs = 2;
  // Interleaved time-major: [t0e0, t0e1, t1e0, t1e1, …].
  input.rewards.resize(10);
  input.rewards << 1, 1, 2, 1, 0, 1, 1, 1, 3, 1;
  input.values.resize(10);
  input.values << 0.5f, 0, 1.0f, 0, 2.0f, 0, 1.5f, 0, 0.5f, 0;
  input.terminated = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0};
  input.truncated = {0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  input.truncation_values = Eigen::VectorXf::Zero(10);
  input.truncation_values[2] = 4.0f;
  input.last_values.resize(2);
  input.last_values << 2.0f, 0.0f;
  return input;
}

TEST(Gae, HandComputedTruncatedAndTerminatedEpisodes) {
  const GaeOutput output = compute_gae(example(), 0.9, 0.5);
  // Env 0, backwards:
  //   t4: δ = 3 + 0.9·2 − 0.5 = 4.3                    Â = 4.3 (bootstraps V(s_5))
  //   t3: terminated: δ = 1 − 1.5 = −0.5               Â = −0.5
  //   t2: δ = 0 + 0.9·1.5 − 2 = −0.65                  Â = −0.65 + 0.45·(−0.5) = −0.875
  //   t1: truncated: δ = 2 + 0.9·4 − 1 = 4.6           Â = 4.6 (no leak from the next episode)
  //   t0: δ = 1 + 0.9·1 − 0.5 = 1.4                    Â = 1.4 + 0.45·4.6 = 3.47
  const float env0[] = {3.47f, 4.6f, -0.875f, -0.5f, 4.3f};
  const float values0[] = {0.5f, 1.0f, 2.0f, 1.5f, 0.5f};
  // Env 1: δ = 1 everywhere; Â_t = 1 + 0.45 Â_{t+1} from Â_4 = 1.
  const float env1[] = {1.78463125f, 1.743625f, 1.6525f, 1.45f, 1.0f};
  for (int t = 0; t < 5; ++t) {
    EXPECT_NEAR(output.advantages[2 * t], env0[t], 1e-5) << "env 0, t " << t;
    EXPECT_NEAR(output.returns[2 * t], env0[t] + values0[t], 1e-5) << "env 0, t " << t;
    EXPECT_NEAR(output.advantages[2 * t + 1], env1[t], 1e-5) << "env 1, t " << t;
    EXPECT_NEAR(output.returns[2 * t + 1], env1[t], 1e-5) << "env 1, t " << t;
  }
}

TEST(Gae, LambdaOneIsTheDiscountedReturnMinusValue) {
  GaeInput input;
  input.n_steps = 3;
  input.n_envs = 1;
  input.rewards = Eigen::Vector3f(1, 2, 3);
  input.values = Eigen::Vector3f(0.3f, -0.2f, 0.7f);
  input.terminated = {0, 0, 1};
  input.truncated = {0, 0, 0};
  input.truncation_values = Eigen::Vector3f::Zero();
  input.last_values = Eigen::VectorXf::Constant(1, 100.0f);  // after a terminal step: unused
  const GaeOutput output = compute_gae(input, 0.5, 1.0);
  EXPECT_NEAR(output.returns[0], 1 + 0.5 * 2 + 0.25 * 3, 1e-6);
  EXPECT_NEAR(output.returns[1], 2 + 0.5 * 3, 1e-6);
  EXPECT_NEAR(output.returns[2], 3, 1e-6);
}

TEST(Gae, MismatchedSizesAreRejected) {
  GaeInput input = example();
  input.rewards.resize(9);
  EXPECT_THROW(compute_gae(input, 0.9, 0.5), Error);
}

TEST(RolloutBuffer, StoresTimeMajorAndMatchesComputeGae) {
  const GaeInput input = example();
  RolloutBuffer buffer(5, 2, 3, 1);
  for (int t = 0; t < 5; ++t) {
    RolloutBuffer::RowMatrix observations = RolloutBuffer::RowMatrix::Constant(2, 3, t);
    observations(1, 0) = 10.0f + t;
    Eigen::MatrixXf actions(1, 2);
    actions << t, -t;
    const auto slice = [&](const Eigen::VectorXf& v) {
      return Eigen::VectorXf(v.segment(2 * t, 2));
    };
    const std::vector<uint8_t> terminated(input.terminated.begin() + 2 * t,
                                          input.terminated.begin() + 2 * t + 2);
    const std::vector<uint8_t> truncated(input.truncated.begin() + 2 * t,
                                         input.truncated.begin() + 2 * t + 2);
    EXPECT_FALSE(buffer.full());
    buffer.add(observations, actions, slice(input.rewards), slice(input.values),
               Eigen::VectorXf::Constant(2, -1.0f * t), terminated, truncated,
               slice(input.truncation_values));
  }
  EXPECT_TRUE(buffer.full());
  buffer.finish(input.last_values, 0.9, 0.5);
  const GaeOutput expected = compute_gae(input, 0.9, 0.5);
  EXPECT_TRUE(buffer.advantages().isApprox(expected.advantages));
  EXPECT_TRUE(buffer.returns().isApprox(expected.returns));
  EXPECT_EQ(buffer.observations()(7, 0), 13.0f);  // t 3, env 1
  EXPECT_EQ(buffer.actions()(7, 0), -3.0f);
  EXPECT_EQ(buffer.log_probs()[6], -3.0f);
  EXPECT_THROW(buffer.add(RolloutBuffer::RowMatrix::Zero(2, 3), Eigen::MatrixXf::Zero(1, 2),
                          Eigen::VectorXf::Zero(2), Eigen::VectorXf::Zero(2),
                          Eigen::VectorXf::Zero(2), {0, 0}, {0, 0}, Eigen::VectorXf::Zero(2)),
               Error);
}

// A finished one-env buffer in which every step ends its episode, so the value targets are the
// rewards themselves: returns R = r, predictions V = v.
RolloutBuffer one_step_episodes(const std::vector<float>& rewards,
                                const std::vector<float>& values) {
  const auto n = static_cast<int64_t>(rewards.size());
  RolloutBuffer buffer(n, 1, 1, 1);
  const RolloutBuffer::RowMatrix observation = RolloutBuffer::RowMatrix::Zero(1, 1);
  for (int64_t t = 0; t < n; ++t) {
    buffer.add(observation, Eigen::MatrixXf::Zero(1, 1), Eigen::VectorXf::Constant(1, rewards[t]),
               Eigen::VectorXf::Constant(1, values[t]), Eigen::VectorXf::Zero(1), {1}, {0},
               Eigen::VectorXf::Zero(1));
  }
  buffer.finish(Eigen::VectorXf::Zero(1), 0.99, 0.95);
  EXPECT_TRUE(buffer.returns().isApprox(Eigen::Map<const Eigen::VectorXf>(rewards.data(), n)));
  return buffer;
}

// 1 − Var[R − V] / Var[R] (population variances, as numpy.var in SB3's explained_variance).
TEST(RolloutBuffer, ExplainedVariance) {
  // Values 0 predict nothing of returns (1, 2).
  EXPECT_NEAR(explained_variance(one_step_episodes({1, 2}, {0, 0})), 0.0, 1e-9);
  // Perfect predictions, and predictions off by a constant, explain everything.
  EXPECT_NEAR(explained_variance(one_step_episodes({1, 2, 4}, {1, 2, 4})), 1.0, 1e-12);
  EXPECT_NEAR(explained_variance(one_step_episodes({1, 2, 4}, {4, 5, 7})), 1.0, 1e-12);
  // R = (1, 2, 3, 4), V = (0, 2, 2, 5): R − V = (1, 0, 1, −1) with variance 0.6875; Var R =
  // 1.25; 1 − 0.55 = 0.45.
  EXPECT_NEAR(explained_variance(one_step_episodes({1, 2, 3, 4}, {0, 2, 2, 5})), 0.45, 1e-7);
  // V = −R: Var[2R] = 4 Var R, so −3: worse than predicting a constant.
  EXPECT_NEAR(explained_variance(one_step_episodes({1, 2, 3}, {-1, -2, -3})), -3.0, 1e-9);
  // Constant returns have nothing to explain: 0 by convention (SB3 reports NaN).
  EXPECT_EQ(explained_variance(one_step_episodes({2, 2}, {0, 1})), 0.0);
}

}  // namespace
}  // namespace tendril::rl
