// The beam tasks: observations, rewards against the seed's own numbers, termination, errors,
// reproducibility, what a viewer sees.
#include "tendril/envs/beam/beam_env.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/error_message.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/beam/arc_path.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs::beam {
namespace {

BeamEnv& task(Env& env) {
  auto* found = find_wrapper<BeamEnv>(env);
  EXPECT_NE(found, nullptr);
  return *found;
}

Action random_action(Rng& rng) {
  Action action(5);
  for (int i = 0; i < 5; ++i) action[i] = static_cast<float>(rng.uniform(-1.0, 1.0));
  return action;
}

// The seed's tables are per-step means of the weighted sum (Sec. VI; spec 003.5): its own
// numbers reproduce.
TEST(FollowReward, TheSeedsTablesAreWeightedSums) {
  EXPECT_NEAR(follow_reward({-40.0, -10.0, -1.0}, 0.053, 0.127, 1.02), -4.41, 1e-12);
  EXPECT_NEAR(follow_reward({-40.0, -10.0, 0.0}, 0.045, 0.128, 1.55), -3.08, 1e-12);
  EXPECT_NEAR(follow_reward({-40.0, -10.0, 0.0}, 0.0475, 0.109, 0.0), -2.99, 1e-12);
  EXPECT_NEAR(follow_reward({-20.0, 0.0, 0.0}, 0.080, 0.3, 2.0), -1.60, 1e-12);
}

TEST(BeamEnv, ObservationsOfTheSeedsModels) {
  for (const auto& [id, observation, size] :
       {std::tuple{"Beam/ArcFollow-v0", "tip", 4},
        std::tuple{"Beam/ArcFollow-v0", "six_points", 14},
        std::tuple{"Beam/TrajectoryFollow-v0", "trajectory", 18},
        std::tuple{"Beam/EllipseFollow-v0", "trajectory", 18}}) {
    auto env = make(id, Config::parse(std::string("observation: ") + observation));
    EXPECT_EQ(env->observation_space().size(), size) << id << " " << observation;
    EXPECT_EQ(env->action_space().size(), 5);
    const Observation first = env->reset(5);
    const BeamEnv& beam = task(*env);
    const Eigen::Vector2d target = beam.target().position();
    // The straight beam's tip, then the target (velocities zero at rest).
    EXPECT_FLOAT_EQ(first[size == 4 ? 0 : 10], 0.0f);
    EXPECT_FLOAT_EQ(first[size == 4 ? 1 : 11], 0.75f);
    const int target_at = size == 18 ? 14 : size - 2;
    EXPECT_FLOAT_EQ(first[target_at], static_cast<float>(target.x()));
    EXPECT_FLOAT_EQ(first[target_at + 1], static_cast<float>(target.y()));
    if (size >= 14) {
      for (int k = 0; k < 5; ++k) {  // torque rows 5, 11, …, 29 at y = 0.125 … 0.725
        EXPECT_FLOAT_EQ(first[2 * k + 1], static_cast<float>(0.125 + 0.15 * k));
      }
    }
    if (size == 18) {
      EXPECT_EQ(first[12], 0.0f);
      EXPECT_EQ(first[13], 0.0f);
      EXPECT_FLOAT_EQ(first[16], static_cast<float>(beam.target().velocity().x()));
    }
  }
}

// Every step's reward is the weighted sum of the metrics it reports, and the energy metric is
// |Σ τ_i θ_i| of the torques applied and the rows' angles after the step.
TEST(BeamEnv, RewardIsTheWeightedSumOfTheReportedMetrics) {
  auto env = make("Beam/EnergyAwareFollow-v0");
  env->reset(2);
  const BeamEnv& beam = task(*env);
  Rng rng(9);
  double largest_energy = 0.0;
  for (int t = 0; t < 60; ++t) {
    const Action action = random_action(rng);
    const Step step = env->step(action);
    const double d = *step.info.get("distance");
    const double v = *step.info.get("velocity_error");
    const double e = *step.info.get("energy");
    EXPECT_NEAR(step.reward, -40.0 * d - 10.0 * v - 1.0 * e, 1e-12);
    double work = 0.0;
    for (int i = 0; i < 5; ++i) {
      work += 4.5 * action[i] * beam.beam().row_angle(beam.spec().lattice.torque_rows[i]);
    }
    EXPECT_NEAR(e, std::abs(work), 1e-9);
    EXPECT_NEAR(d, (beam.beam().tip_position() - beam.target().position()).norm(), 1e-15);
    EXPECT_NEAR(v, (beam.beam().tip_velocity() - beam.target().velocity()).norm(), 1e-15);
    largest_energy = std::max(largest_energy, e);
    if (step.terminated || step.truncated) break;
  }
  EXPECT_GT(largest_energy, 0.1);

  auto normalised = make("Beam/EnergyAwareFollow-v0", Config::parse("energy_units: normalised"));
  auto metres = make("Beam/EnergyAwareFollow-v0");
  normalised->reset(4);
  metres->reset(4);
  const Action action = Action::Constant(5, 0.6f);
  const double in_units = *normalised->step(action).info.get("energy");
  EXPECT_NEAR(*metres->step(action).info.get("energy"), 4.5 * in_units, 1e-9);
}

TEST(BeamEnv, CasesAndTasksHaveTheSeedsWeightsAndTorques) {
  EXPECT_EQ(task(*make("Beam/ArcFollow-v0")).spec().weights.distance, -20.0);
  EXPECT_EQ(task(*make("Beam/ArcFollow-v0")).spec().weights.velocity, 0.0);
  const BeamTaskSpec trajectory = task(*make("Beam/TrajectoryFollow-v0")).spec();
  EXPECT_EQ(trajectory.weights.distance, -40.0);
  EXPECT_EQ(trajectory.weights.velocity, -10.0);
  EXPECT_EQ(trajectory.torque_scale, 4.5);
  EXPECT_EQ(task(*make("Beam/EnergyAwareFollow-v0")).spec().weights.energy, -1.0);
  EXPECT_EQ(task(*make("Beam/EllipseFollow-v0")).spec().torque_scale, 8.0);
  const auto case3 = make("Beam/TrajectoryFollow-v0",
                          Config::parse("{distance_weight: -400, velocity_weight: -200}"));
  EXPECT_EQ(task(*case3).spec().weights.distance, -400.0);
}

TEST(BeamEnv, ArcTasksDrawTheSeedsRadiiAndSpeeds) {
  for (const auto& [id, slowest] :
       {std::pair{"Beam/ArcFollow-v0", 0.5}, std::pair{"Beam/TrajectoryFollow-v0", 0.1}}) {
    auto env = make(id);
    double radius_low = 1.0, radius_high = 0.0, speed_low = 1.0, speed_high = 0.0;
    for (uint64_t seed = 0; seed < 200; ++seed) {
      env->reset(seed);
      const auto& arc = dynamic_cast<const ArcPath&>(task(*env).target());
      radius_low = std::min(radius_low, arc.radius());
      radius_high = std::max(radius_high, arc.radius());
      speed_low = std::min(speed_low, arc.angular_velocity());
      speed_high = std::max(speed_high, arc.angular_velocity());
    }
    EXPECT_GE(radius_low, 0.2);
    EXPECT_LT(radius_low, 0.21);
    EXPECT_LE(radius_high, 0.6);
    EXPECT_GT(radius_high, 0.59);
    EXPECT_GE(speed_low, slowest);
    EXPECT_LT(speed_low, slowest + 0.01);
    EXPECT_NEAR(speed_high, 0.5, 0.01);
  }
  auto fixed = make("Beam/ArcFollow-v0", Config::parse("radius: [0.5, 0.5]"));
  fixed->reset(1);
  EXPECT_EQ(dynamic_cast<const ArcPath&>(task(*fixed).target()).radius(), 0.5);
}

TEST(BeamEnv, ActionsSaturateAtTheActuatorsLimit) {
  auto a = make("Beam/ArcFollow-v0");
  auto b = make("Beam/ArcFollow-v0");
  a->reset(1);
  b->reset(1);
  Action big(5), limit(5);
  big << 3.0f, -7.0f, 1.0f, 0.5f, -1.5f;
  limit << 1.0f, -1.0f, 1.0f, 0.5f, -1.0f;
  EXPECT_EQ(a->step(big).observation, b->step(limit).observation);
  EXPECT_EQ(task(*a).beam().couples().torques()[1], -4.5);
}

TEST(BeamEnv, BadActionsAreRefused) {
  auto env = make("Beam/ArcFollow-v0");
  env->reset(0);
  EXPECT_NE(testing::error_message([&] { env->step(Action::Zero(4)); }).find("5"),
            std::string::npos);
  Action bad = Action::Zero(5);
  bad[2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(testing::error_message([&] { env->step(bad); }), "no error");
}

TEST(BeamEnv, SameSeedSameEpisodeOtherSeedAnother) {
  const auto rollout = [](uint64_t seed) {
    auto env = make("Beam/TrajectoryFollow-v0");
    std::vector<Observation> trace{env->reset(seed)};
    Rng rng(17);
    for (int t = 0; t < 250; ++t) {  // past the 200-step limit: includes a reset
      const Step step = env->step(random_action(rng));
      trace.push_back(step.terminated || step.truncated ? env->reset() : step.observation);
    }
    return trace;
  };
  EXPECT_EQ(rollout(3), rollout(3));
  EXPECT_NE(rollout(3), rollout(4));
}

TEST(BeamEnv, MaxDistanceEndsTheEpisode) {
  auto env = make("Beam/ArcFollow-v0", Config::parse("max_distance: 0.15"));
  env->reset(0);
  const double start = (task(*env).beam().tip_position() - task(*env).target().position()).norm();
  ASSERT_GT(start, 0.15);  // the target starts on its arc, far from the straight beam's tip
  const Step step = env->step(Action::Zero(5));
  EXPECT_TRUE(step.terminated);
  EXPECT_FALSE(step.truncated);
  EXPECT_NEAR(step.reward, -20.0 * *step.info.get("distance"), 1e-12);

  auto never = make("Beam/ArcFollow-v0");
  never->reset(0);
  for (int t = 0; t < 199; ++t) ASSERT_FALSE(never->step(Action::Zero(5)).terminated);
  EXPECT_TRUE(never->step(Action::Zero(5)).truncated);  // the registered 200-step limit
}

TEST(BeamEnv, NonFiniteBeamEndsTheEpisodeWithThePenalty) {
  auto env = make("Beam/ArcFollow-v0");
  const Observation first = env->reset(0);
  BeamEnv& beam = task(*env);
  physics::LatticeState state = beam.beam().lattice().state();
  state.velocities(0, 40) = std::numeric_limits<double>::infinity();
  beam.beam().lattice().set_state(state);
  const Step step = env->step(Action::Zero(5));
  EXPECT_TRUE(step.terminated);
  EXPECT_EQ(step.reward, -100.0);
  EXPECT_EQ(*step.info.get("nan"), 1.0);
  EXPECT_EQ(step.observation, first);
  EXPECT_TRUE(env->reset(1).allFinite());  // a reset re-arms the beam
  EXPECT_FALSE(env->step(Action::Zero(5)).terminated);
}

TEST(BeamEnv, BadParametersAreNamed) {
  const auto error_for = [](const std::string& id, const std::string& yaml) {
    return testing::error_message([&] { make(id, Config::parse(yaml, "beam.yaml")); });
  };
  EXPECT_NE(error_for("Beam/ArcFollow-v0", "radius: [0.6, 0.2]").find("radius"), std::string::npos);
  EXPECT_NE(error_for("Beam/ArcFollow-v0", "observation: everything").find("observation"),
            std::string::npos);
  EXPECT_NE(error_for("Beam/ArcFollow-v0", "torque_scal: 3").find("torque_scal"),
            std::string::npos);
  EXPECT_NE(error_for("Beam/ArcFollow-v0", "time_step: 0.03").find("control_period"),
            std::string::npos);
  EXPECT_NE(error_for("Beam/EllipseFollow-v0", "levels: [{eccentricity: [0.5, 1.5]}]")
                .find("eccentricity"),
            std::string::npos);
  EXPECT_NE(
      error_for("Beam/EllipseFollow-v0", "levels: [{eccentricty: [0.5, 0.6]}]").find("eccentricty"),
      std::string::npos);
  EXPECT_NE(error_for("Beam/ArcFollow-v0", "integrator: rk4").find("integrator"),
            std::string::npos);
  EXPECT_EQ(error_for("Beam/ArcFollow-v0",
                      "{radius: [0.5, 0.5], integrator: symplectic_euler, time_step: 2.5e-4}"),
            "no error");
}

TEST(BeamEnv, ExplicitAndImplicitBeamsFollowTheSameTorques) {
  // The task on the explicit reference lattice and on the default BDF2 one, under gentle
  // torques: their tips stay within 2 cm over 5 s.
  auto implicit = make("Beam/ArcFollow-v0");
  auto explicit_ =
      make("Beam/ArcFollow-v0", Config::parse("{integrator: symplectic_euler, time_step: 2.5e-4}"));
  implicit->reset(8);
  explicit_->reset(8);
  double worst = 0.0;
  double farthest_from_rest = 0.0;  // the comparison means something only if the tip moved
  for (int t = 0; t < 100; ++t) {
    Action action(5);
    for (int i = 0; i < 5; ++i) action[i] = static_cast<float>(0.2 * std::sin(0.3 * t + i));
    implicit->step(action);
    explicit_->step(action);
    const Eigen::Vector2d tip = task(*implicit).beam().tip_position();
    worst = std::max(worst, (tip - task(*explicit_).beam().tip_position()).norm());
    farthest_from_rest = std::max(farthest_from_rest, (tip - Eigen::Vector2d(0, 0.75)).norm());
  }
  EXPECT_LT(worst, 0.02);
  EXPECT_GT(farthest_from_rest, 0.05);
}

TEST(BeamEnv, SceneHasTheLatticeTheTargetAndItsPath) {
  auto env = make("Beam/EllipseFollow-v0");
  env->reset(0);
  env->step(Action::Constant(5, 0.1f));
  Scene scene;
  ASSERT_TRUE(env->describe_scene(scene));
  ASSERT_EQ(scene.lattices.size(), 1u);
  EXPECT_EQ(scene.lattices[0].nodes.cols(), 93);
  EXPECT_EQ(scene.lattices[0].springs.size(), 272u);
  EXPECT_EQ(scene.lattices[0].nodes.row(2).norm(), 0.0);
  ASSERT_EQ(scene.spheres.size(), 1u);
  EXPECT_EQ(scene.spheres[0].role, "target");
  ASSERT_EQ(scene.paths.size(), 1u);
  EXPECT_NEAR((scene.paths[0].points.col(0) - Eigen::Vector3d(0, 0.70, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(scene.time, 0.05, 1e-12);
}

}  // namespace
}  // namespace tendril::envs::beam
