// Behaviour shared by the four Elastica control cases (SPEC M2), checked on each registered id.
#include "tendril/envs/elastica/elastica_arm_env.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <ostream>

#include "elastica_test_support.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs::elastica {
namespace {

using testing::make_case;

struct CaseFacts {
  std::string id;
  int observation_size;
  int action_size;
  int64_t episode_steps;
  int substeps;
  int n_elements;
  double time_step;  // s
  double nan_penalty;
  int target_offset;  // where the target position sits in the observation
  std::size_t obstacles;
};

// SPEC M2's table.
const CaseFacts kCases[] = {
    {"Elastica/Tracking3D-v0", 44, 12, 7142, 7, 20, 2e-4, -1000.0, 37, 0},
    {"Elastica/OrientedReach-v0", 52, 18, 1428, 7, 20, 2e-4, -10000.0, 41, 0},
    {"Elastica/StructuredObstacles-v0", 160, 2, 3571, 14, 50, 1e-4, -100.0, 37, 8},
    {"Elastica/UnstructuredObstacles-v0", 220, 4, 3571, 14, 50, 1e-4, -100.0, 37, 12},
};

void PrintTo(const CaseFacts& facts, std::ostream* out) { *out << facts.id; }

class ElasticaCase : public ::testing::TestWithParam<CaseFacts> {};

TEST_P(ElasticaCase, SpacesNumericsAndTimeLimit) {
  const CaseFacts& facts = GetParam();
  auto made = make_case(facts.id);
  EXPECT_EQ(made.env->observation_space().size(), facts.observation_size);
  EXPECT_EQ(made.env->action_space().size(), facts.action_size);
  EXPECT_EQ(made.env->action_space().low(), Eigen::VectorXf::Constant(facts.action_size, -1.0f));
  EXPECT_EQ(made.env->action_space().high(), Eigen::VectorXf::Constant(facts.action_size, 1.0f));
  auto* limit = dynamic_cast<TimeLimit*>(made.env.get());
  ASSERT_NE(limit, nullptr);
  EXPECT_EQ(limit->max_episode_steps(), facts.episode_steps);
  EXPECT_EQ(made.task->substeps_per_action(), facts.substeps);
  EXPECT_EQ(made.task->arm().rod.n_elements(), facts.n_elements);
  EXPECT_EQ(made.task->arm().rod.time_step(), facts.time_step);
  // One RL step is 1.4 ms of simulated time in every case.
  const Observation first = made.env->reset(0);
  EXPECT_EQ(first.size(), facts.observation_size);
  made.env->step(Action::Zero(facts.action_size));
  EXPECT_NEAR(made.task->time(), 1.4e-3, 1e-15);
}

TEST_P(ElasticaCase, ObservationStartsWithTheRodNodesAndTipVelocity) {
  const CaseFacts& facts = GetParam();
  auto made = make_case(facts.id);
  made.env->reset(3);
  Step step;
  for (int i = 0; i < 20; ++i) step = made.env->step(Action::Constant(facts.action_size, 0.5f));
  ASSERT_FALSE(step.terminated);
  const physics::Rod& rod = made.task->arm().rod;
  testing::expect_rod_block(step.observation, rod);
  const Eigen::Vector3d velocity = rod.tip_velocity();
  ASSERT_GT(velocity.norm(), 1e-3) << "the arm should be moving";
  EXPECT_FLOAT_EQ(step.observation[33], static_cast<float>(velocity.norm()));
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(step.observation[34 + c], static_cast<float>(velocity[c] / velocity.norm()));
    EXPECT_FLOAT_EQ(step.observation[facts.target_offset + c],
                    static_cast<float>(made.task->target_position()[c]));
  }
  // Distance as reported.
  EXPECT_NEAR(*step.info.get("distance"),
              (rod.tip_position() - made.task->target_position()).norm(), 1e-12);
}

TEST_P(ElasticaCase, ViewerSeesAllNodesTheTargetAndTheObstacles) {
  const CaseFacts& facts = GetParam();
  auto made = make_case(facts.id);
  made.env->reset(1);
  made.env->step(Action::Constant(facts.action_size, -0.3f));
  const Eigen::Matrix3Xd nodes = made.task->node_positions();
  ASSERT_EQ(nodes.cols(), facts.n_elements + 1);
  const Eigen::Vector3d base =
      facts.n_elements == 20 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.0, 0.5, 0.0);
  EXPECT_EQ(Eigen::Vector3d(nodes.col(0)), base);
  EXPECT_EQ(Eigen::Vector3d(nodes.col(facts.n_elements)), made.task->arm().rod.tip_position());
  EXPECT_EQ(made.task->obstacles().size(), facts.obstacles);
  EXPECT_TRUE(made.task->target_position().allFinite());
}

TEST_P(ElasticaCase, InvalidActionsRaise) {
  const CaseFacts& facts = GetParam();
  auto made = make_case(facts.id);
  made.env->reset(0);
  EXPECT_THROW(made.env->step(Action::Zero(facts.action_size + 1)), Error);
  EXPECT_THROW(made.env->step(Action::Zero(facts.action_size - 1)), Error);
  Action bad = Action::Zero(facts.action_size);
  bad[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(made.env->step(bad), Error);
}

TEST_P(ElasticaCase, PlantedNanEndsTheEpisodeWithTheCasePenalty) {
  const CaseFacts& facts = GetParam();
  auto made = make_case(facts.id);
  made.env->reset(0);
  const Step before = made.env->step(Action::Constant(facts.action_size, 0.2f));
  ASSERT_FALSE(before.terminated);
  EXPECT_EQ(*before.info.get("nan"), 0.0);

  made.task->arm().rod.mutable_state().velocities(0, facts.n_elements / 2) =
      std::numeric_limits<double>::quiet_NaN();
  const Step after = made.env->step(Action::Constant(facts.action_size, 0.2f));
  EXPECT_TRUE(after.terminated);
  EXPECT_FALSE(after.truncated);
  EXPECT_EQ(after.reward, facts.nan_penalty);
  EXPECT_EQ(*after.info.get("nan"), 1.0);
  EXPECT_EQ(*after.info.get("is_success"), 0.0);
  EXPECT_TRUE(std::isfinite(*after.info.get("distance")));
  ASSERT_TRUE(after.observation.allFinite());
  EXPECT_EQ(after.observation, before.observation);  // the last finite one
  // The same keys every step, so a logger's columns stay aligned.
  ASSERT_EQ(after.info.entries().size(), before.info.entries().size());
  for (std::size_t k = 0; k < after.info.entries().size(); ++k) {
    EXPECT_EQ(after.info.entries()[k].first, before.info.entries()[k].first);
  }

  // A reset brings back a healthy arm.
  EXPECT_TRUE(made.env->reset(0).allFinite());
  const Step healthy = made.env->step(Action::Zero(facts.action_size));
  EXPECT_FALSE(healthy.terminated);
  EXPECT_EQ(*healthy.info.get("nan"), 0.0);
}

TEST_P(ElasticaCase, SeededEpisodeIsReproducible) {
  const CaseFacts& facts = GetParam();
  auto first = make_case(facts.id), second = make_case(facts.id);
  const auto run = [&](Env& env, std::vector<Observation>& observations,
                       std::vector<double>& rewards) {
    Rng actions(8);
    observations.push_back(env.reset(21));
    for (int i = 0; i < 40; ++i) {
      const Step step = env.step(env.action_space().sample(actions));
      observations.push_back(step.observation);
      rewards.push_back(step.reward);
    }
  };
  std::vector<Observation> obs_a, obs_b, obs_c;
  std::vector<double> rewards_a, rewards_b, rewards_c;
  run(*first.env, obs_a, rewards_a);
  run(*second.env, obs_b, rewards_b);
  run(*first.env, obs_c, rewards_c);  // the same environment again after a seeded reset
  ASSERT_EQ(obs_a.size(), 41u);
  for (std::size_t i = 0; i < obs_a.size(); ++i) {
    ASSERT_EQ(obs_a[i], obs_b[i]) << "step " << i;
    ASSERT_EQ(obs_a[i], obs_c[i]) << "step " << i;
  }
  EXPECT_EQ(rewards_a, rewards_b);
  EXPECT_EQ(rewards_a, rewards_c);
  EXPECT_NE(obs_a.front(), obs_a.back()) << "the arm should have moved";
}

TEST_P(ElasticaCase, UnknownParametersAreRejected) {
  const CaseFacts& facts = GetParam();
  try {
    make(facts.id, Config::parse("n_element: 30"));
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown key 'n_element'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(facts.id), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, ElasticaCase, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<CaseFacts>& info) {
                           const std::string& id = info.param.id;
                           return id.substr(id.find('/') + 1, id.find('-') - id.find('/') - 1);
                         });

}  // namespace
}  // namespace tendril::envs::elastica
