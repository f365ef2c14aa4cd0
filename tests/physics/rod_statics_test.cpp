// Static validation of the Cosserat rod against closed-form solutions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rod_test_support.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

using testing::add_uniform_damping;
using testing::settle;

// A clamped rod pulled along its axis: n = EA (e − 1) and the lab force Qᵀn/e balance F, so
// e = EA / (EA − F) and the elongation is F L / (EA − F).
TEST(RodStatics, AxialStretchUnderEndForce) {
  RodSpec spec;
  spec.n_elements = 20;
  spec.length = 1.0;
  spec.radius = 0.05;
  spec.density = 1000.0;
  spec.youngs_modulus = 1.0e5;
  spec.shear_modulus = spec.youngs_modulus / 1.5;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitY();
  spec.time_step = 1.0e-4;
  Rod rod(spec);
  rod.add<FixedEnd>();
  const double force = 50.0;
  rod.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(force, 0, 0), 0.5);
  add_uniform_damping(rod, 30.0);
  ASSERT_TRUE(settle(rod, 20.0, 1e-7));

  const double ea = spec.youngs_modulus * std::numbers::pi * spec.radius * spec.radius;
  const double expected = force * spec.length / (ea - force);
  const double elongation = rod.tip_position().x() - spec.length;
  EXPECT_NEAR(elongation, expected, 0.01 * expected);
  EXPECT_NEAR(elongation, expected, 1e-6 * expected)
      << "uniform stretch is exact in the discrete model";
  // Volume conservation: r = r̂ / √e.
  const double dilatation = 1.0 + expected / spec.length;
  EXPECT_NEAR(rod.state().radii[5], spec.radius / std::sqrt(dilatation), 1e-8);
}

// Timoshenko cantilever under a transverse tip force (PyElastica's validation case): the tip
// deflects by F L / (α_c G A) (shear) + F L³ / (3 E I) (bending).
double cantilever_tip_deflection(int n_elements) {
  RodSpec spec;
  spec.n_elements = n_elements;
  spec.length = 3.0;
  spec.radius = 0.25;
  spec.density = 5000.0;
  spec.youngs_modulus = 1.0e6;
  spec.shear_modulus = 1.0e4;
  spec.shear_coefficient = 4.0 / 3.0;
  spec.direction = Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitX();
  spec.time_step = 0.01 * spec.length / n_elements;
  Rod rod(spec);
  rod.add<FixedEnd>();
  rod.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(-15.0, 0, 0), 2.0);
  add_uniform_damping(rod, 1.4);  // about critical for the first mode (ω₁ ≈ 0.69 rad/s)
  EXPECT_TRUE(settle(rod, 200.0, 1e-7)) << "n = " << n_elements;
  return -rod.tip_position().x();
}

// The clamp holds the whole first element (node 0 and the directors of element 0, as in
// PyElastica), so the discrete cantilever is stiffer by O(l̂/L): first-order convergence.
TEST(RodStatics, TimoshenkoCantileverConvergesToClosedForm) {
  const double force = 15.0, length = 3.0, radius = 0.25;
  const double area = std::numbers::pi * radius * radius;
  const double second_moment = std::numbers::pi * std::pow(radius, 4) / 4.0;
  const double expected = force * length / (4.0 / 3.0 * 1.0e4 * area) +
                          force * std::pow(length, 3) / (3.0 * 1.0e6 * second_moment);
  double previous_error = INFINITY;
  for (int n : {50, 100, 200}) {
    const double deflection = cantilever_tip_deflection(n);
    const double error = std::abs(deflection - expected);
    std::printf("cantilever n = %3d: tip deflection %.6f m, closed form %.6f m, error %.3f%%\n", n,
                deflection, expected, 100.0 * error / expected);
    if (n >= 100) {
      EXPECT_LT(error, 0.02 * expected) << "n = " << n;
    }
    EXPECT_LT(error, previous_error) << "error must shrink as n doubles, n = " << n;
    previous_error = error;
  }
}

// Free rod under gravity: position Verlet is exact for constant acceleration.
TEST(RodStatics, FreeFallIsExact) {
  RodSpec spec;
  spec.n_elements = 5;
  spec.time_step = 1e-3;
  Rod rod(spec);
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  rod.add<Gravity>(g);
  const Eigen::Matrix3Xd start = rod.state().positions;
  ASSERT_TRUE(rod.advance(1000));
  const double t = rod.time();
  EXPECT_NEAR(t, 1.0, 1e-12);
  for (int j = 0; j <= spec.n_elements; ++j) {
    EXPECT_LT((rod.state().positions.col(j) - (start.col(j) + 0.5 * g * t * t)).norm(), 1e-9);
  }
}

// Element forces reach the nodes half-and-half: a uniform force per element on a free rod
// accelerates it as a whole, F_total / m_total, exactly.
TEST(RodStatics, ElementForcesSplitBetweenNodes) {
  RodSpec spec;
  spec.n_elements = 4;
  spec.time_step = 1e-3;
  Rod rod(spec);
  auto& loads = rod.add<ElementForces>();
  loads.forces().colwise() = Eigen::Vector3d(0.0, 0.0, 2.0);
  ASSERT_TRUE(rod.advance(100));
  const double mass = rod.model().node_masses.sum();
  const double expected_speed = 4 * 2.0 / mass * rod.time();
  for (int j = 0; j <= 4; ++j) EXPECT_NEAR(rod.state().velocities(2, j), expected_speed, 1e-9);
}

// A point mass on the tip weighs on the rod exactly like an end force m g: a clamped cantilever
// under gravity settles to the same shape either way; the tip node carries the extra mass.
TEST(RodStatics, TipMassWeighsLikeAnEndForce) {
  RodSpec spec;
  spec.n_elements = 10;
  spec.length = 0.5;
  spec.radius = 0.02;
  spec.youngs_modulus = 1.0e6;
  spec.shear_modulus = spec.youngs_modulus / 3.0;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitZ();
  spec.time_step = 1.0e-4;
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  const double tip_mass = 0.05;

  RodSpec loaded_spec = spec;
  loaded_spec.tip_mass = tip_mass;
  Rod loaded(loaded_spec);
  loaded.add<FixedEnd>();
  loaded.add<Gravity>(g);
  add_uniform_damping(loaded, 40.0);
  Rod pushed(spec);
  pushed.add<FixedEnd>();
  pushed.add<Gravity>(g);
  pushed.add<EndForces>(Eigen::Vector3d::Zero(), tip_mass * g);
  add_uniform_damping(pushed, 40.0);
  EXPECT_DOUBLE_EQ(loaded.model().node_masses[10], pushed.model().node_masses[10] + tip_mass);

  ASSERT_TRUE(settle(loaded, 20.0, 1e-7));
  ASSERT_TRUE(settle(pushed, 20.0, 1e-7));
  const double sag = -pushed.tip_position().z();
  ASSERT_GT(sag, 0.05) << "the load must bend the rod visibly";
  EXPECT_NEAR(loaded.tip_position().z(), pushed.tip_position().z(), 1e-5 * sag);
  EXPECT_NEAR(loaded.tip_position().x(), pushed.tip_position().x(), 1e-5 * sag);
}

}  // namespace
}  // namespace tendril::physics
