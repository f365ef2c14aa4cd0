// Many rods of one model stepped in lockstep (RodPool) against the same rods stepped alone.
#include "tendril/physics/rod/rod_pool.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "rod_test_support.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"

namespace tendril::physics {
namespace {

// Sets rod `index` moving: node velocities and element rotation rates that vary along the rod
// and from rod to rod (small enough to stay in the common branches, or, with `violent`, with
// rotations beyond 0.1 rad per step that take Rod's general formulas).
void plant_motion(Rod& rod, int index, bool violent = false) {
  RodState& state = rod.mutable_state();
  const int n = rod.n_elements();
  for (int j = 0; j <= n; ++j) {
    for (int k = 0; k < 3; ++k) {
      state.velocities(k, j) = 0.02 * std::sin(0.7 * j + 1.3 * k + 0.9 * index) * j / n;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      state.angular_velocities(k, i) = 0.3 * std::cos(0.5 * i + 2.1 * k + 1.7 * index);
    }
  }
  if (violent) state.angular_velocities(0, n / 2) = 12000.0;
  rod.state_changed();
}

// Exact equality of the configuration and rates of `rod` and rod `index` of `pool`.
void expect_identical(const RodPool& pool, int index, const Rod& rod, const std::string& when) {
  RodState state;
  state.resize(pool.model());
  pool.get_state(index, state);
  const RodState& alone = rod.state();
  EXPECT_TRUE(state.positions == alone.positions) << "positions of rod " << index << when;
  EXPECT_TRUE(state.velocities == alone.velocities) << "velocities of rod " << index << when;
  EXPECT_TRUE(state.directors == alone.directors) << "directors of rod " << index << when;
  EXPECT_TRUE(state.angular_velocities == alone.angular_velocities)
      << "angular velocities of rod " << index << when;
  EXPECT_EQ(pool.time(index), rod.time()) << "time of rod " << index << when;
}

Eigen::VectorXd random_targets(Rng& rng, int size, double spread) {
  Eigen::VectorXd targets(size);
  // Beyond [−1, 1] at times: the muscles clamp, in the pool as alone.
  for (int k = 0; k < size; ++k) targets[k] = rng.uniform(-spread, spread);
  return targets;
}

// The case-1 Elastica arm (FixedEnd, InternalDamping, SplineActuation): 11 rods (a full block
// of kRodLanes and a partial one), each from its own initial motion under its own random
// muscle targets, for 300 RL actions of 7 steps (0.42 s) — bit for bit equal to 11 lone arms.
TEST(RodPool, ElasticaArmsMatchLoneArmsBitForBit) {
  const ElasticaArmSpec spec = ElasticaArmSpec::tracking();
  const int count = 11;
  RodPool pool(build_elastica_arm(spec).rod, count);
  std::vector<ElasticaArm> arms;
  std::vector<Rng> rngs;
  for (int r = 0; r < count; ++r) {
    arms.push_back(build_elastica_arm(spec));
    plant_motion(arms[r].rod, r);
    pool.set_state(r, arms[r].rod.state());
    rngs.emplace_back(17, r);
  }
  for (int action = 0; action < 300; ++action) {
    for (int r = 0; r < count; ++r) {
      const Eigen::VectorXd targets = random_targets(rngs[r], spec.actuation.action_size(), 1.2);
      arms[r].muscles->set_targets(targets);
      pool.set_targets(r, targets);
      ASSERT_TRUE(arms[r].rod.advance(7));
    }
    ASSERT_TRUE(pool.advance(7));
  }
  for (int r = 0; r < count; ++r) {
    expect_identical(pool, r, arms[r].rod, " after 300 actions");
    EXPECT_TRUE(pool.muscles(r).current() == arms[r].muscles->current());
    EXPECT_EQ(pool.tip_position(r), arms[r].rod.tip_position());
    EXPECT_EQ(pool.tip_velocity(r), arms[r].rod.tip_velocity());
  }
  // The arms really moved apart: the test compares different trajectories.
  EXPECT_GT((pool.tip_position(0) - pool.tip_position(1)).norm(), 1e-2);
}

// Every part the pool mirrors, in one rod: a clamp, analytical damping, internal damping,
// gravity, ramped end forces and rate-limited muscles; calls of 1, 5 and 13 steps (Rod merges
// half kinematic steps within a call); one rod rotating beyond 0.1 rad per step at first (Rod's
// general rotation formula and large frame angles).
TEST(RodPool, EveryMirroredPartMatchesLoneRodsBitForBit) {
  RodSpec spec;
  spec.n_elements = 12;
  spec.length = 0.6;
  spec.radius = 0.02;
  spec.youngs_modulus = 2.0e6;
  spec.shear_modulus = spec.youngs_modulus / 3.0;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitZ();
  spec.time_step = 5.0e-5;
  SplineActuationSpec muscles;
  muscles.control_points = 3;
  muscles.directions = {true, true, true};
  muscles.max_torque = 0.5;
  muscles.max_change_per_step = 0.01;
  const auto build = [&] {
    Rod rod(spec);
    rod.add<FixedEnd>();
    rod.add<AnalyticalLinearDamping>(0.5, 1e-4);
    rod.add<InternalDamping>(2.0);
    rod.add<Gravity>();
    rod.add<SplineActuation>(muscles);
    rod.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.3, -0.2), 0.01);
    return rod;
  };
  const int count = 5;
  RodPool pool(build(), count);
  std::vector<Rod> rods;
  std::vector<Rng> rngs;
  for (int r = 0; r < count; ++r) {
    rods.push_back(build());
    plant_motion(rods[r], r, r == 2);
    pool.set_state(r, rods[r].state());
    rngs.emplace_back(5, r);
  }
  const int calls[] = {1, 5, 13};
  for (int action = 0; action < 150; ++action) {
    const int steps = calls[action % 3];
    for (int r = 0; r < count; ++r) {
      const Eigen::VectorXd targets = random_targets(rngs[r], muscles.action_size(), 1.0);
      dynamic_cast<SplineActuation&>(*rods[r].parts()[4]).set_targets(targets);
      pool.set_targets(r, targets);
      ASSERT_TRUE(rods[r].advance(steps));
    }
    ASSERT_TRUE(pool.advance(steps));
    if (action == 0) {
      expect_identical(pool, 2, rods[2], " after the violent first call");
      // Both rare branches were taken: 12000 rad/s is 0.6 rad per step (beyond 0.1 rad), and
      // frame angles beyond asin(0.2) = 0.201 rad leave the series of θ / sin θ.
      double largest_angle = 0.0;
      for (int j = 0; j + 1 < spec.n_elements; ++j) {
        largest_angle = std::max(largest_angle, rods[2].curvatures().col(j).norm() *
                                                    rods[2].model().rest_voronoi_lengths[j]);
      }
      EXPECT_GT(largest_angle, 0.25);
    }
  }
  for (int r = 0; r < count; ++r) expect_identical(pool, r, rods[r], " after 150 calls");
}

// A free rod under gravity moving as a whole: position Verlet is exact for constant
// acceleration, x(t) = x₀ + u t + ½ g t², in every rod with its own velocity u.
TEST(RodPool, FreeFallWithOwnVelocitiesIsExact) {
  RodSpec spec;
  spec.n_elements = 5;
  spec.time_step = 1e-3;
  Rod prototype(spec);
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  prototype.add<Gravity>(g);
  const int count = 9;
  RodPool pool(prototype, count);
  const Eigen::Matrix3Xd start = prototype.state().positions;
  RodState state = prototype.state();
  for (int r = 0; r < count; ++r) {
    state.velocities.colwise() = Eigen::Vector3d(0.1 * r, -0.2 * r, 0.3);
    pool.set_state(r, state);
  }
  ASSERT_TRUE(pool.advance(1000));
  for (int r = 0; r < count; ++r) {
    const double t = pool.time(r);
    EXPECT_NEAR(t, 1.0, 1e-12);
    const Eigen::Vector3d u(0.1 * r, -0.2 * r, 0.3);
    for (int j = 0; j <= spec.n_elements; ++j) {
      EXPECT_LT((pool.node_position(r, j) - (start.col(j) + u * t + 0.5 * g * t * t)).norm(), 1e-9)
          << "rod " << r << " node " << j;
    }
  }
}

// Timoshenko cantilever under a transverse tip force (as in rod_statics_test): every rod of the
// pool, whatever its initial motion, settles to F L / (α_c G A) + F L³ / (3 E I) within 2 % at
// 100 elements (the discrete clamp's O(l̂/L) stiffening is about 1 %).
TEST(RodPool, CantileversSettleToTimoshenkoDeflection) {
  const double force = 15.0, length = 3.0, radius = 0.25;
  RodSpec spec;
  spec.n_elements = 100;
  spec.length = length;
  spec.radius = radius;
  spec.density = 5000.0;
  spec.youngs_modulus = 1.0e6;
  spec.shear_modulus = 1.0e4;
  spec.shear_coefficient = 4.0 / 3.0;
  spec.direction = Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitX();
  spec.time_step = 0.01 * spec.length / spec.n_elements;
  Rod prototype(spec);
  prototype.add<FixedEnd>();
  prototype.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(-force, 0, 0), 2.0);
  testing::add_uniform_damping(prototype, 1.4);
  const int count = 3;
  RodPool pool(prototype, count);
  for (int r = 1; r < count; ++r) {
    Rod moving(spec);
    plant_motion(moving, r);
    pool.set_state(r, moving.state());
  }
  RodState state;
  state.resize(pool.model());
  const int chunk = static_cast<int>(0.01 / spec.time_step);
  bool settled = false;
  while (!settled && pool.time(0) < 200.0) {
    ASSERT_TRUE(pool.advance(chunk));
    settled = true;
    for (int r = 0; r < count; ++r) {
      pool.get_state(r, state);
      settled = settled && state.velocities.colwise().norm().maxCoeff() < 1e-7;
    }
  }
  ASSERT_TRUE(settled);
  const double area = std::numbers::pi * radius * radius;
  const double second_moment = std::numbers::pi * std::pow(radius, 4) / 4.0;
  const double expected = force * length / (4.0 / 3.0 * 1.0e4 * area) +
                          force * std::pow(length, 3) / (3.0 * 1.0e6 * second_moment);
  for (int r = 0; r < count; ++r) {
    EXPECT_NEAR(-pool.tip_position(r).x(), expected, 0.02 * expected) << "rod " << r;
  }
}

// A rod that blows up stops, as a lone Rod does; the others go on unchanged.
TEST(RodPool, NonFiniteRodStopsAndOthersGoOn) {
  const ElasticaArmSpec spec = ElasticaArmSpec::tracking();
  RodPool pool(build_elastica_arm(spec).rod, 3);
  ElasticaArm reference = build_elastica_arm(spec);
  plant_motion(reference.rod, 0);
  RodState bad = reference.rod.state();
  for (int r = 0; r < 3; ++r) pool.set_state(r, reference.rod.state());
  bad.velocities(0, 5) = std::numeric_limits<double>::quiet_NaN();
  pool.set_state(1, bad);
  EXPECT_FALSE(pool.is_finite(1));
  EXPECT_TRUE(pool.is_finite(0));
  EXPECT_FALSE(pool.advance(70));
  ASSERT_TRUE(reference.rod.advance(70));
  expect_identical(pool, 0, reference.rod, "");
  expect_identical(pool, 2, reference.rod, "");
  RodState stopped;
  stopped.resize(pool.model());
  pool.get_state(1, stopped);
  EXPECT_TRUE(stopped.positions == bad.positions);
  EXPECT_EQ(pool.time(1), bad.time);
  // A finite state brings it back.
  pool.set_state(1, reference.rod.state());
  EXPECT_TRUE(pool.advance(7));
}

TEST(RodPool, BadInputRaisesError) {
  const ElasticaArmSpec spec = ElasticaArmSpec::tracking();
  const ElasticaArm arm = build_elastica_arm(spec);
  EXPECT_THROW(RodPool(arm.rod, 0), Error);
  RodPool pool(arm.rod, 4);

  // A state of a rod of another size.
  RodSpec small;
  small.n_elements = 5;
  const Rod other(small);
  try {
    pool.set_state(0, other.state());
    FAIL() << "a 5-element state went into a 20-element pool";
  } catch (const Error& error) {
    EXPECT_NE(error.what_wrong().find("positions is 3 × 6"), std::string::npos)
        << error.what_wrong();
  }
  RodState wrong;
  EXPECT_THROW(pool.get_state(0, wrong), Error);
  EXPECT_THROW(pool.set_state(4, arm.rod.state()), Error);
  EXPECT_THROW(pool.set_state(-1, arm.rod.state()), Error);
  EXPECT_THROW(static_cast<void>(pool.node_position(0, 21)), Error);
  EXPECT_THROW(pool.set_targets(0, Eigen::VectorXd::Zero(5)), Error);
  EXPECT_THROW(pool.set_targets(0, Eigen::VectorXd::Constant(12, NAN)), Error);

  // Parts it does not mirror, and implicit rods.
  Rod couples(small);
  couples.add<FixedEnd>();
  couples.add<ElementCouples>();
  try {
    RodPool unsupported(couples, 2);
    FAIL() << "ElementCouples went into a pool";
  } catch (const Error& error) {
    EXPECT_NE(error.what_wrong().find("part 1"), std::string::npos) << error.what_wrong();
    EXPECT_NE(error.what_wrong().find("ElementCouples"), std::string::npos) << error.what_wrong();
  }
  RodSpec implicit = small;
  implicit.integrator = RodIntegrator::kBackwardEuler;
  EXPECT_THROW(RodPool(Rod(implicit), 2), Error);
  // No muscles to command.
  RodPool plain(other, 2);
  EXPECT_FALSE(plain.has_muscles());
  EXPECT_THROW(plain.set_targets(0, Eigen::VectorXd::Zero(1)), Error);
}

}  // namespace
}  // namespace tendril::physics
