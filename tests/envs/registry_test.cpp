#include "tendril/envs/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>

#include "support/error_message.hpp"
#include "support/required_env_params.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/classic_control/pendulum.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs {
namespace {

using testing::error_message;

TEST(Registry, ListsTheBuiltinReferenceTasks) {
  EXPECT_EQ(registered_ids(), (std::vector<std::string>{"Beam/ArcFollow-v0",
                                                        "Beam/EllipseFollow-v0",
                                                        "Beam/EnergyAwareFollow-v0",
                                                        "Beam/TrajectoryFollow-v0",
                                                        "CartPole-v1",
                                                        "Elastica/OrientedReach-v0",
                                                        "Elastica/StructuredObstacles-v0",
                                                        "Elastica/Tracking3D-v0",
                                                        "Elastica/UnstructuredObstacles-v0",
                                                        "Identity-v0",
                                                        "IdentityBox-v0",
                                                        "MountainCarContinuous-v0",
                                                        "Pendulum-v1",
                                                        "PneumaticArm/LearnedReach-v0",
                                                        "PneumaticArm/Reach-v0",
                                                        "PneumaticArm/Robot-v0",
                                                        "Safety/DoubleIntegrator-v0",
                                                        "Safety/DubinsCar-v0",
                                                        "SmaLimb/LearnedReach-v0",
                                                        "SmaLimb/LearnedSafety-v0",
                                                        "SmaLimb/Robot-v0",
                                                        "TendonArm/LearnedReach-v0",
                                                        "TendonArm/Reach-v0",
                                                        "TendonArm/Robot-v0",
                                                        "UR5/Reach-v0"}));
  EXPECT_EQ(builtin_registry().spec("Pendulum-v1").max_episode_steps, 200);
  EXPECT_EQ(builtin_registry().spec("CartPole-v1").max_episode_steps, 500);
  EXPECT_EQ(builtin_registry().spec("MountainCarContinuous-v0").max_episode_steps, 999);
  EXPECT_EQ(builtin_registry().spec("Identity-v0").max_episode_steps, 100);
  EXPECT_EQ(builtin_registry().spec("IdentityBox-v0").max_episode_steps, 100);
  EXPECT_EQ(builtin_registry().spec("Beam/ArcFollow-v0").max_episode_steps, 200);
  EXPECT_EQ(builtin_registry().spec("Beam/EllipseFollow-v0").max_episode_steps, 260);
}

TEST(Registry, UnknownIdIsNamedWithTheRegisteredIds) {
  EXPECT_EQ(error_message([] { make("Pendulum-v0"); }),
            "envs::make: unknown environment id 'Pendulum-v0'; registered ids: "
            "Beam/ArcFollow-v0, Beam/EllipseFollow-v0, Beam/EnergyAwareFollow-v0, "
            "Beam/TrajectoryFollow-v0, CartPole-v1, "
            "Elastica/OrientedReach-v0, Elastica/StructuredObstacles-v0, Elastica/Tracking3D-v0, "
            "Elastica/UnstructuredObstacles-v0, Identity-v0, IdentityBox-v0, "
            "MountainCarContinuous-v0, Pendulum-v1, PneumaticArm/LearnedReach-v0, "
            "PneumaticArm/Reach-v0, "
            "PneumaticArm/Robot-v0, Safety/DoubleIntegrator-v0, Safety/DubinsCar-v0, "
            "SmaLimb/LearnedReach-v0, SmaLimb/LearnedSafety-v0, SmaLimb/Robot-v0, "
            "TendonArm/LearnedReach-v0, TendonArm/Reach-v0, TendonArm/Robot-v0, UR5/Reach-v0");
}

TEST(Registry, UnknownParameterIsNamedWithTheEnvironment) {
  const Config config = Config::parse("env:\n  params: {g: 9.81, gravity: 3}\n", "exp.yaml");
  EXPECT_EQ(error_message([&] { make("Pendulum-v1", config.child("env").child("params")); }),
            "exp.yaml: unknown key 'env.params.gravity', not a parameter of environment "
            "'Pendulum-v1'");
  const Config cart = Config::parse("mass: 2\n", "cart.yaml");
  EXPECT_EQ(error_message([&] { make("CartPole-v1", cart); }),
            "cart.yaml: unknown key 'mass', not a parameter of environment 'CartPole-v1'");
}

TEST(Registry, MakeAppliesParametersAndTheTimeLimit) {
  const auto env = make("Pendulum-v1", Config::parse("g: 2.5\nmax_episode_steps: 3\n"));
  auto* limit = dynamic_cast<TimeLimit*>(env.get());
  ASSERT_NE(limit, nullptr);
  EXPECT_EQ(limit->max_episode_steps(), 3);
  auto& pendulum = dynamic_cast<Pendulum&>(limit->inner());
  env->reset(0);
  pendulum.set_state(0.5, 0.0);
  env->step(Action::Zero(1));
  EXPECT_NEAR(pendulum.theta_dot(), 1.5 * 2.5 * std::sin(0.5) * 0.05, 1e-12);
  EXPECT_FALSE(env->step(Action::Zero(1)).truncated);
  EXPECT_TRUE(env->step(Action::Zero(1)).truncated);
  EXPECT_NE(error_message([] {
              make("CartPole-v1", Config::parse("max_episode_steps: 0"));
            }).find("max_episode_steps must be at least 1"),
            std::string::npos);
}

TEST(Registry, AddingAnEnvironmentIsOneCall) {
  Registry registry;
  registry.add({"Family/Swing-v2", &Pendulum::create, std::nullopt, "a pendulum without limit"});
  EXPECT_TRUE(registry.contains("Family/Swing-v2"));
  const auto env = registry.make("Family/Swing-v2");
  EXPECT_NE(dynamic_cast<Pendulum*>(env.get()), nullptr);  // no time limit registered
  EXPECT_NE(error_message([&] {
              registry.add({"Family/Swing-v2", &Pendulum::create, {}, ""});
            }).find("already registered"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              registry.add({"Swing", &Pendulum::create, {}, ""});
            }).find("not of the form Name-v<N>"),
            std::string::npos);
  EXPECT_THROW(registry.add({"Empty-v0", nullptr, {}, ""}), Error);
}

// Under random actions every task but CartPole (whose pole falls within a few dozen steps), the
// pneumatic arm's reach (whose tip wanders out of its workspace boundary), the UR5's reach (whose
// arm soon touches the table, the box or itself), the safe-control tasks (which drift past
// their absolute bounds) and the limb's safety task (which bends out of its 30° disc) runs until
// the time limit cuts it: an early termination there is a failure (for the soft-arm cases the only
// termination is a non-finite state), as is a NaN flag or a non-finite reward. Environments without
// a registered limit (robots that run for hours) run 200 steps.
TEST(Registry, EveryBuiltinEnvironmentRunsAnEpisodeToItsLimit) {
  const std::set<std::string> terminates_under_random_actions{
      "CartPole-v1",           "PneumaticArm/LearnedReach-v0",
      "PneumaticArm/Reach-v0", "Safety/DoubleIntegrator-v0",
      "Safety/DubinsCar-v0",   "SmaLimb/LearnedSafety-v0",
      "UR5/Reach-v0"};
  for (const std::string& id : registered_ids()) {
    const auto env = make(id, testing::required_env_params(id));
    const std::optional<int64_t> registered = builtin_registry().spec(id).max_episode_steps;
    const int64_t limit = registered.value_or(200);
    Rng rng(1);
    env->reset(0);
    int64_t steps = 0;
    Step step;
    while (!step.terminated && !step.truncated && steps < limit) {
      step = env->step(env->action_space().sample(rng));
      ++steps;
      ASSERT_TRUE(env->observation_space().contains(step.observation))
          << id << " step " << steps << ": " << step.observation.transpose();
      ASSERT_TRUE(std::isfinite(step.reward)) << id << " step " << steps;
      ASSERT_EQ(step.info.get("nan").value_or(0.0), 0.0) << id << " step " << steps;
      ASSERT_FALSE(step.terminated && step.truncated) << id;
      if (step.truncated) {
        EXPECT_EQ(steps, limit) << id;
      }
    }
    if (terminates_under_random_actions.count(id) != 0) {
      EXPECT_TRUE(step.terminated) << id;
      EXPECT_LT(steps, limit) << id;
      continue;
    }
    EXPECT_FALSE(step.terminated) << id << " terminated after " << steps << " steps";
    if (registered) EXPECT_TRUE(step.truncated) << id << " ran past its limit";
  }
}

}  // namespace
}  // namespace tendril::envs
