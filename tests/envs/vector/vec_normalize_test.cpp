#include "tendril/envs/vector/vec_normalize.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

constexpr double kPrior = RunningMeanStd::kInitialCount;
const VecNormalize::Options kObservationsOnly{.normalize_observation = true,
                                              .normalize_reward = false};
const VecNormalize::Options kRewardsOnly{.normalize_observation = false, .normalize_reward = true};

// Three ScriptedEnvs observing [steps, resets, seed], whose episodes end after 2, 3 and 4 steps;
// with `options`, under a shared VecNormalize.
std::unique_ptr<ThreadedVecEnv> scripted_raw(int num_threads = 1) {
  return std::make_unique<ThreadedVecEnv>(
      3,
      [](int i) {
        return std::make_unique<ScriptedEnv>(ScriptedEnv::Options{1.0, 2 + i});
      },
      num_threads);
}

std::unique_ptr<VecNormalize> scripted(VecNormalize::Options options, int num_threads = 1) {
  return std::make_unique<VecNormalize>(scripted_raw(num_threads), options);
}

const BatchMatrix kScriptedActions = BatchMatrix::Zero(3, 2);

// Statistics of every sample pooled by hand with SB3's prior (count 1e-4, mean 0, var 1):
// n = 1e-4 + N, mean = Σx / n, var = (1e-4 (1 + mean²) + Σ(x − mean)²) / n per component.
struct Pooled {
  double count;
  Eigen::VectorXd mean, var;
};

Pooled pooled(const std::vector<Eigen::VectorXd>& samples) {
  const Eigen::Index size = samples.front().size();
  Pooled result{kPrior + static_cast<double>(samples.size()), Eigen::VectorXd::Zero(size),
                Eigen::VectorXd::Zero(size)};
  for (const auto& x : samples) result.mean += x;
  result.mean /= result.count;
  result.var = kPrior * (1.0 + result.mean.array().square()).matrix();
  for (const auto& x : samples) result.var += (x - result.mean).array().square().matrix();
  result.var /= result.count;
  return result;
}

TEST(VecNormalize, SharedStatisticsEqualThoseOfTheStackedBatches) {
  auto raw = scripted_raw();
  auto normalized = scripted(kObservationsOnly);
  std::vector<Eigen::VectorXd> samples;  // every raw observation row the statistics saw
  const auto collect = [&](const BatchMatrix& batch) {
    for (Eigen::Index i = 0; i < batch.rows(); ++i) {
      samples.push_back(batch.row(i).transpose().cast<double>());
    }
  };
  collect(raw->reset(10));
  const BatchMatrix first = normalized->reset(10);
  for (int t = 0; t < 6; ++t) {
    if (t > 0) collect(raw->step(kScriptedActions).observations);
    const BatchMatrix& observations =
        t > 0 ? normalized->step(kScriptedActions).observations : first;
    const RunningMeanStd& shared = normalized->observation_statistics();
    const Pooled expected = pooled(samples);
    EXPECT_NEAR(shared.count(), expected.count, 1e-9) << t;
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(shared.mean()[j], expected.mean[j], 1e-9) << t << "," << j;
      EXPECT_NEAR(shared.var()[j], expected.var[j], 1e-9) << t << "," << j;
      for (int i = 0; i < 3; ++i) {
        const double raw_value = samples[samples.size() - 3 + i][j];
        const double scaled = (raw_value - expected.mean[j]) / std::sqrt(expected.var[j] + 1e-8);
        EXPECT_NEAR(observations(i, j), std::clamp(scaled, -10.0, 10.0), 1e-5) << t;
      }
    }
  }
  EXPECT_NEAR(normalized->observation_statistics().count(), 18.0 + kPrior, 1e-12);
}

// Every observation, final observation, reward and flag of `steps` random steps, in one buffer.
std::vector<float> normalized_trace(const std::string& id, int num_threads, int steps,
                                    RunningMeanStd& observation_statistics) {
  VecNormalize vec(
      std::make_unique<ThreadedVecEnv>(
          3, [&](int) { return std::make_unique<EpisodeStatistics>(make(id)); }, num_threads),
      VecNormalize::Options{});
  Rng rng(5, 17);
  std::vector<float> out;
  const auto append = [&](const BatchMatrix& m) {
    out.insert(out.end(), m.data(), m.data() + m.size());
  };
  append(vec.reset(21));
  BatchMatrix actions(3, vec.action_space().size());
  for (int t = 0; t < steps; ++t) {
    for (int i = 0; i < 3; ++i) actions.row(i) = vec.action_space().sample(rng).transpose();
    const VecStep& step = vec.step(actions);
    append(step.observations);
    append(step.final_observations);
    out.insert(out.end(), step.rewards.data(), step.rewards.data() + step.rewards.size());
    for (int i = 0; i < 3; ++i) out.push_back(static_cast<float>(step.done(i)));
  }
  observation_statistics = vec.observation_statistics();
  return out;
}

TEST(VecNormalize, OneAndTwoThreadsGiveBitIdenticalSteps) {
  for (const std::string id : {"Pendulum-v1", "CartPole-v1"}) {
    RunningMeanStd synchronous_statistics, threaded_statistics;
    const std::vector<float> synchronous = normalized_trace(id, 1, 400, synchronous_statistics);
    const std::vector<float> threaded = normalized_trace(id, 2, 400, threaded_statistics);
    ASSERT_EQ(synchronous.size(), threaded.size());
    EXPECT_EQ(std::memcmp(synchronous.data(), threaded.data(), synchronous.size() * sizeof(float)),
              0)
        << id;
    EXPECT_EQ(synchronous_statistics, threaded_statistics) << id;
  }
}

// Observes [0]; its rewards follow `rewards` (cycled across episodes) and each episode
// terminates after `episode_length` steps.
class RewardScript : public Env {
 public:
  RewardScript(std::vector<double> rewards, int episode_length)
      : rewards_(std::move(rewards)), episode_length_(episode_length) {}

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> = std::nullopt) override {
    steps_ = 0;
    return Observation::Zero(1);
  }
  Step step(const Action&) override {
    Step result;
    result.observation = Observation::Zero(1);
    result.reward = rewards_[next_++ % rewards_.size()];
    result.terminated = ++steps_ >= episode_length_;
    return result;
  }

 private:
  std::vector<double> rewards_;
  int episode_length_;
  int steps_ = 0;
  std::size_t next_ = 0;
  Space observation_space_ = Space::box(1, -1.0f, 1.0f);
  Space action_space_ = Space::box(1, -1.0f, 1.0f);
};

std::unique_ptr<VecNormalize> reward_scripts(const std::array<std::vector<double>, 3>& rewards,
                                             const std::array<int, 3>& episode_lengths) {
  auto inner = std::make_unique<ThreadedVecEnv>(3, [&](int i) {
    return std::make_unique<EpisodeStatistics>(
        std::make_unique<RewardScript>(rewards[i], episode_lengths[i]));
  });
  return std::make_unique<VecNormalize>(std::move(inner), kRewardsOnly);
}

TEST(VecNormalize, ScalesRewardsByTheStdOfTheSharedDiscountedReturn) {
  const std::array<std::vector<double>, 3> rewards = {
      std::vector<double>{1.0, -2.0, 0.5}, {3.0}, {-1.0, 4.0}};
  const std::array<int, 3> lengths = {2, 3, 4};
  auto vec = reward_scripts(rewards, lengths);
  vec->reset(0);
  const BatchMatrix actions = BatchMatrix::Zero(3, 1);
  std::vector<Eigen::VectorXd> returns_seen;  // every R_i the return statistics saw
  std::array<double, 3> running_return{}, episode_return{};
  std::array<int, 3> steps{};
  for (int t = 0; t < 9; ++t) {
    const VecStep& step = vec->step(actions);
    std::array<double, 3> reward{};
    for (int i = 0; i < 3; ++i) {
      reward[i] = rewards[i][t % rewards[i].size()];
      running_return[i] = 0.99 * running_return[i] + reward[i];
      returns_seen.push_back(Eigen::VectorXd::Constant(1, running_return[i]));
    }
    const Pooled expected = pooled(returns_seen);
    const RunningMeanStd& shared = vec->return_statistics();
    EXPECT_NEAR(shared.count(), expected.count, 1e-9) << t;
    EXPECT_NEAR(shared.mean()[0], expected.mean[0], 1e-9) << t;
    EXPECT_NEAR(shared.var()[0], expected.var[0], 1e-9) << t;
    for (int i = 0; i < 3; ++i) {
      const double scaled = reward[i] / std::sqrt(expected.var[0] + 1e-8);
      EXPECT_NEAR(step.rewards[i], std::clamp(scaled, -10.0, 10.0), 1e-5) << t << "," << i;
      episode_return[i] += reward[i];
      const bool ends = ++steps[i] == lengths[i];
      ASSERT_EQ(step.done(i), ends) << t << "," << i;
      if (ends) {
        // R_i restarts; the episode statistics below the normalizer stay raw.
        EXPECT_EQ(step.infos[i].get("episode_return"), episode_return[i]);
        running_return[i] = episode_return[i] = 0.0;
        steps[i] = 0;
      }
      EXPECT_NEAR(vec->returns()[i], running_return[i], 1e-12) << t << "," << i;
    }
  }
}

TEST(VecNormalize, ClipsScaledRewardsAtTen) {
  // Equal returns in every env leave the return variance near the prior's share, ~1/3:
  // ±100 / 0.577 is far beyond the clip.
  for (const double reward : {100.0, -100.0}) {
    auto vec = reward_scripts({std::vector<double>{reward}, {reward}, {reward}}, {5, 5, 5});
    vec->reset(0);
    const VecStep& step = vec->step(BatchMatrix::Zero(3, 1));
    for (int i = 0; i < 3; ++i) EXPECT_EQ(step.rewards[i], reward > 0 ? 10.0f : -10.0f);
  }
  // Frozen at std 1e-3: 5 and −5 clip, 5e-4 does not.
  auto vec = reward_scripts({std::vector<double>{5.0}, {-5.0}, {5e-4}}, {5, 5, 5});
  const RunningMeanStd tight = RunningMeanStd::from_array(std::vector<double>{1e4, 0.0, 1e-6}, 1);
  vec->set_return_state(tight, Eigen::VectorXd::Zero(3));
  vec->set_training(false);
  vec->reset(0);
  const VecStep& step = vec->step(BatchMatrix::Zero(3, 1));
  EXPECT_EQ(step.rewards[0], 10.0f);
  EXPECT_EQ(step.rewards[1], -10.0f);
  EXPECT_NEAR(step.rewards[2], 5e-4 / std::sqrt(1e-6 + 1e-8), 1e-6);  // ≈ 0.4975
}

TEST(VecNormalize, FinalObservationsUseTheSameStatisticsAsObservations) {
  auto raw = scripted_raw();
  auto normalized = scripted(kObservationsOnly);
  raw->reset(3);
  normalized->reset(3);
  int finished = 0;
  for (int t = 0; t < 6; ++t) {
    const VecStep& expected = raw->step(kScriptedActions);
    const VecStep& step = normalized->step(kScriptedActions);
    const RunningMeanStd& shared = normalized->observation_statistics();
    const auto normalize = [&](const BatchMatrix& rows, int i) -> Eigen::RowVectorXf {
      return shared.normalize(rows.row(i).transpose().cast<double>(), 1e-8, 10.0)
          .cast<float>()
          .transpose();
    };
    for (int i = 0; i < 3; ++i) {
      ASSERT_EQ(step.done(i), expected.done(i));
      EXPECT_EQ(step.observations.row(i), normalize(expected.observations, i)) << t << "," << i;
      EXPECT_EQ(step.final_observations.row(i), normalize(expected.final_observations, i))
          << t << "," << i;
      if (step.done(i)) {
        ++finished;
        EXPECT_NE(step.final_observations.row(i), step.observations.row(i));
      } else {
        EXPECT_EQ(step.final_observations.row(i), step.observations.row(i));
      }
    }
  }
  EXPECT_EQ(finished, 3 + 2 + 1);  // episodes of 2, 3 and 4 steps within 6 steps
}

TEST(VecNormalize, FrozenStatisticsDoNotChange) {
  auto raw = scripted_raw();
  auto vec = scripted(VecNormalize::Options{});
  raw->reset(1);
  vec->reset(1);
  for (int t = 0; t < 3; ++t) {
    raw->step(kScriptedActions);
    vec->step(kScriptedActions);
  }
  VecNormalize& normalizer = *vec;
  normalizer.set_training(false);
  const RunningMeanStd observations = normalizer.observation_statistics();
  const RunningMeanStd returns = normalizer.return_statistics();
  for (int t = 0; t < 5; ++t) {
    const VecStep& expected = raw->step(kScriptedActions);
    const VecStep& step = vec->step(kScriptedActions);
    for (int i = 0; i < 3; ++i) {
      const Eigen::RowVectorXf frozen =
          observations
              .normalize(expected.observations.row(i).transpose().cast<double>(), 1e-8, 10.0)
              .cast<float>()
              .transpose();
      EXPECT_EQ(step.observations.row(i), frozen);
      EXPECT_EQ(step.rewards[i], static_cast<float>(returns.scale(1.0, 1e-8, 10.0)));
    }
  }
  vec->reset(2);
  vec->step(kScriptedActions);
  EXPECT_EQ(normalizer.observation_statistics(), observations);
  EXPECT_EQ(normalizer.return_statistics(), returns);
  EXPECT_EQ(normalizer.returns(), Eigen::VectorXd::Zero(3));  // not accumulated while frozen
}

TEST(VecNormalize, InstalledStateContinuesTheRunExactly) {
  auto original = scripted(VecNormalize::Options{});
  auto copy = scripted(VecNormalize::Options{});
  copy->set_training(false);  // steps its envs alike, gathering nothing
  original->reset(7);
  copy->reset(7);
  for (int t = 0; t < 5; ++t) {
    original->step(kScriptedActions);
    copy->step(kScriptedActions);
  }

  const VecNormalize& source = *original;
  ASSERT_NE(source.returns(), Eigen::VectorXd::Zero(3));
  VecNormalize& target = *copy;
  const int size = source.observation_statistics().size();
  target.set_observation_statistics(
      RunningMeanStd::from_array(source.observation_statistics().to_array(), size));
  target.set_return_state(RunningMeanStd::from_array(source.return_statistics().to_array(), 1),
                          source.returns());
  target.set_training(true);
  EXPECT_EQ(target.observation_statistics(), source.observation_statistics());
  EXPECT_EQ(target.return_statistics(), source.return_statistics());
  for (int t = 0; t < 6; ++t) {
    const VecStep& expected = original->step(kScriptedActions);
    const VecStep& step = copy->step(kScriptedActions);
    EXPECT_EQ(step.observations, expected.observations) << t;
    EXPECT_EQ(step.final_observations, expected.final_observations) << t;
    EXPECT_EQ(step.rewards, expected.rewards) << t;
  }

  // A mismatched state is refused and changes nothing.
  const RunningMeanStd before = target.return_statistics();
  EXPECT_THROW(target.set_observation_statistics(RunningMeanStd(2)), Error);
  EXPECT_THROW(target.set_return_state(RunningMeanStd(1), Eigen::VectorXd::Zero(2)), Error);
  EXPECT_THROW(target.set_return_state(RunningMeanStd(2), Eigen::VectorXd::Zero(3)), Error);
  EXPECT_EQ(target.return_statistics(), before);
  EXPECT_EQ(target.observation_statistics(), source.observation_statistics());
}

// A snapshot of the vector env holds the statistics, the running returns and every environment:
// a fresh one loaded from it continues exactly.
TEST(VecNormalize, SnapshotsContinueTheRunExactly) {
  auto original = scripted(VecNormalize::Options{});
  original->reset(7);
  for (int t = 0; t < 5; ++t) original->step(kScriptedActions);
  ASSERT_TRUE(original->supports_snapshots());
  Snapshot bytes;
  SnapshotWriter out(bytes);
  original->save_state(out, /*environments=*/true);

  auto copy = scripted(VecNormalize::Options{});
  copy->reset(99);
  SnapshotReader in(bytes);
  EXPECT_TRUE(copy->load_state(in));
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(copy->observation_statistics(), original->observation_statistics());
  EXPECT_EQ(copy->returns(), original->returns());
  for (int t = 0; t < 6; ++t) {
    const VecStep& expected = original->step(kScriptedActions);
    const VecStep& step = copy->step(kScriptedActions);
    EXPECT_EQ(step.observations, expected.observations) << t;
    EXPECT_EQ(step.rewards, expected.rewards) << t;
  }

  // Without the environments: the statistics alone, and the environments need a reset.
  Snapshot statistics_only;
  SnapshotWriter statistics_writer(statistics_only);
  original->save_state(statistics_writer, /*environments=*/false);
  auto fresh = scripted(VecNormalize::Options{});
  SnapshotReader statistics_reader(statistics_only);
  EXPECT_FALSE(fresh->load_state(statistics_reader));
  EXPECT_EQ(fresh->observation_statistics(), original->observation_statistics());
  EXPECT_THROW(fresh->step(kScriptedActions), Error);

  // A vector env of another size is refused.
  VecNormalize other(
      std::make_unique<ThreadedVecEnv>(2, [](int) { return std::make_unique<ScriptedEnv>(); }),
      VecNormalize::Options{});
  SnapshotReader mismatch(bytes);
  EXPECT_THROW(other.load_state(mismatch), Error);
}

TEST(VecNormalize, SpacesAndOptionsAreChecked) {
  auto vec = scripted(VecNormalize::Options{});
  EXPECT_EQ(vec->observation_space().describe(), "Box(3, [-10, 10])");
  EXPECT_THROW(vec->step(kScriptedActions), Error);  // a reset comes first
  EXPECT_EQ(scripted(kRewardsOnly)->observation_space().describe(),
            ScriptedEnv().observation_space().describe());
  EXPECT_THROW(VecNormalize(nullptr, VecNormalize::Options{}), Error);
  VecNormalize::Options bad;
  bad.gamma = 1.5;
  EXPECT_THROW(VecNormalize(scripted_raw(), bad), Error);
}

}  // namespace
}  // namespace tendril::envs
