// Dynamic validation: natural frequency, energy conservation, damping laws.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "rod_test_support.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

using testing::kBetaL;
using testing::start_first_mode;

// A slender clamped rod along x (d1 = y, d2 = z) set vibrating in its first mode: node
// velocities V φ(x) along y and element rotation rates V φ'(x) about d2.
RodSpec slender_spec() {
  RodSpec spec;
  spec.n_elements = 100;
  spec.length = 1.0;
  spec.radius = 0.01;
  spec.density = 1000.0;
  spec.youngs_modulus = 1.0e6;
  spec.shear_modulus = spec.youngs_modulus / 1.5;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitY();
  spec.time_step = 1.0e-4;
  return spec;
}

TEST(RodDynamics, FirstNaturalFrequencyOfCantilever) {
  const RodSpec spec = slender_spec();
  Rod rod(spec);
  rod.add<FixedEnd>();
  start_first_mode(rod, 1e-3);

  // Zero crossings of the tip's transverse displacement are half a period apart.
  std::vector<double> crossings;
  double previous = 0.0;
  ASSERT_TRUE(rod.advance(1));
  previous = rod.tip_position().y();
  while (rod.time() < 25.0) {
    ASSERT_TRUE(rod.advance(1));
    const double current = rod.tip_position().y();
    if ((previous < 0.0) != (current < 0.0)) {
      const double fraction = previous / (previous - current);
      crossings.push_back(rod.time() - (1.0 - fraction) * rod.time_step());
    }
    previous = current;
  }
  ASSERT_GE(crossings.size(), 3u);
  const double half_period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double measured = std::numbers::pi / half_period;

  const double area = std::numbers::pi * spec.radius * spec.radius;
  const double second_moment = area * area / (4.0 * std::numbers::pi);
  const double expected = std::pow(kBetaL / spec.length, 2) *
                          std::sqrt(spec.youngs_modulus * second_moment / (spec.density * area));
  std::printf("first natural frequency: measured %.6f rad/s, Euler-Bernoulli %.6f rad/s (%.3f%%)\n",
              measured, expected, 100.0 * (measured - expected) / expected);
  EXPECT_NEAR(measured, expected, 0.02 * expected);
}

TEST(RodDynamics, UndampedEnergyDriftIsBelowOneThousandth) {
  Rod rod(slender_spec());
  rod.add<FixedEnd>();
  start_first_mode(rod, 2e-3);
  const double initial = rod.energies().total();
  ASSERT_GT(initial, 0.0);
  double worst = 0.0;
  for (int chunk = 0; chunk < 1000; ++chunk) {
    ASSERT_TRUE(rod.advance(100));
    worst = std::max(worst, std::abs(rod.energies().total() - initial) / initial);
  }
  std::printf("energy: largest relative deviation over 1e5 steps %.3e\n", worst);
  EXPECT_LT(worst, 1e-3);
  // The energy really moved between kinetic and elastic forms (the test is not vacuous).
  EXPECT_GT(rod.energies().bend_twist, 1e-3 * initial);
}

TEST(RodDynamics, AnalyticalDampingDecaysExactly) {
  RodSpec spec;
  spec.n_elements = 8;
  spec.time_step = 1e-3;
  Rod rod(spec);
  const double translational = 12.0, rotational = 0.02;
  rod.add<AnalyticalLinearDamping>(translational, rotational);
  rod.mutable_state().velocities.colwise() = Eigen::Vector3d(0.3, -0.2, 0.1);
  rod.state_changed();
  ASSERT_TRUE(rod.advance(500));
  const double area = std::numbers::pi * spec.radius * spec.radius;
  // Rigid translation has no internal forces: v(t) = v0 exp(−γ_t t / (ρA)).
  const double factor = std::exp(-translational * rod.time() / (spec.density * area));
  for (int j = 0; j <= spec.n_elements; ++j) {
    EXPECT_LT((rod.state().velocities.col(j) - factor * Eigen::Vector3d(0.3, -0.2, 0.1)).norm(),
              1e-10);  // round-off of the stiff internal forces of a rigid rod
  }
}

TEST(RodDynamics, InternalDampingDissipatesEnergy) {
  RodSpec spec = slender_spec();
  Rod rod(spec);
  rod.add<FixedEnd>();
  rod.add<InternalDamping>(0.05);
  start_first_mode(rod, 2e-3);
  double previous = rod.energies().total();
  for (int chunk = 0; chunk < 20; ++chunk) {
    ASSERT_TRUE(rod.advance(1000));
    const double energy = rod.energies().total();
    EXPECT_LT(energy, previous);
    previous = energy;
  }
}

// The damping law's magnitude: a rigidly translating rod has no internal forces, and each node
// carries ν v l of force per element length l on a mass ρ A l per length, so every velocity
// decays as exp(−ν t / (ρ A)). Explicit in time: (1 − h ν/(ρA))ⁿ, within 0.01 % of the
// exponential here (n (hν/ρA)²/2 ≈ 10⁻⁴), so the bound is 0.2 %. (ν is kept small enough for the
// explicit rotational damping, ν h / (ρ I) < 1.)
TEST(RodDynamics, InternalDampingSlowsARigidTranslationAtTheModelsRate) {
  RodSpec spec;
  spec.n_elements = 8;
  spec.time_step = 1e-4;
  Rod rod(spec);
  const double nu = 20.0;  // kg/(m·s); ν/(ρA) = 2.55 /s for the default 5 cm radius
  rod.add<InternalDamping>(nu);
  const Eigen::Vector3d v0(0.3, -0.2, 0.1);
  rod.mutable_state().velocities.colwise() = v0;
  rod.state_changed();
  ASSERT_TRUE(rod.advance(3000));
  const double area = std::numbers::pi * spec.radius * spec.radius;
  const double factor = std::exp(-nu * rod.time() / (spec.density * area));
  ASSERT_LT(factor, 0.5);  // the decay is substantial
  for (int j = 0; j <= spec.n_elements; ++j) {
    EXPECT_LT((rod.state().velocities.col(j) - factor * v0).norm(), 2e-3 * factor * v0.norm())
        << "node " << j << ": " << rod.state().velocities.col(j).transpose() << " vs "
        << (factor * v0).transpose();
  }
}

}  // namespace
}  // namespace tendril::physics
