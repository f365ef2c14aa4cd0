// The implicit integrators (backward Euler, BDF2) against closed forms of the schemes and of
// the rod: statics at any step, a cantilever's frequency and numerical damping, energy decay,
// the physical damping laws, order of accuracy against position Verlet, failures and snapshots.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

#include "rod_test_support.hpp"
#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

using testing::add_uniform_damping;
using testing::kBetaL;
using testing::settle;
using testing::start_first_mode;

// A cantilever along x (d1 = y, d2 = z) whose first mode is ω₁ ≈ 7 rad/s.
RodSpec cantilever(RodIntegrator integrator, double time_step) {
  RodSpec spec;
  spec.n_elements = 40;
  spec.length = 0.5;
  spec.radius = 0.01;
  spec.density = 1000.0;
  spec.youngs_modulus = 1.0e7;
  spec.shear_modulus = spec.youngs_modulus / 1.5;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitY();
  spec.time_step = time_step;
  spec.integrator = integrator;
  return spec;
}

double euler_bernoulli_first_mode(const RodSpec& spec) {
  const double area = std::numbers::pi * spec.radius * spec.radius;
  const double second_moment = area * area / (4.0 * std::numbers::pi);
  return std::pow(kBetaL / spec.length, 2) *
         std::sqrt(spec.youngs_modulus * second_moment / (spec.density * area));
}

struct Oscillation {
  double frequency = 0.0;   // rad/s, from zero crossings of the tip's y
  double decay_rate = 0.0;  // 1/s of the amplitude, from the energy: E ∝ exp(−2 λ t)
  bool energy_never_grew = true;
};

// Advances a rod started in its first mode for `duration` seconds (steps of its time step);
// the decay is measured from `settled` seconds on (after BDF2's backward-Euler first step).
Oscillation measure(Rod& rod, double duration, double settled = 0.0) {
  Oscillation result;
  std::vector<double> crossings;
  double previous = rod.tip_position().y();
  double energy = rod.energies().total();
  double settled_energy = -1.0, settled_time = 0.0;
  const double h = rod.time_step();
  while (rod.time() < duration - 0.5 * h) {
    EXPECT_TRUE(rod.advance(1));
    const double current = rod.tip_position().y();
    if ((previous < 0.0) != (current < 0.0)) {
      crossings.push_back(rod.time() - h * current / (current - previous));
    }
    previous = current;
    const double now = rod.energies().total();
    if (now > energy * (1.0 + 1e-9)) result.energy_never_grew = false;
    energy = now;
    if (settled_energy < 0.0 && rod.time() >= settled) {
      settled_energy = energy;
      settled_time = rod.time();
    }
  }
  EXPECT_GE(crossings.size(), 4u);
  const double half_period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  result.frequency = std::numbers::pi / half_period;
  result.decay_rate = -std::log(energy / settled_energy) / (2.0 * (rod.time() - settled_time));
  return result;
}

// One step of a scheme on y' = iω y multiplies y by z (the principal root for BDF2 at a
// constant step). Numerical frequency arg z / h, amplitude decay rate −ln|z| / h.
std::complex<double> amplification(RodIntegrator integrator, double omega_h) {
  const std::complex<double> i_wh(0.0, omega_h);
  if (integrator == RodIntegrator::kBackwardEuler) return 1.0 / (1.0 - i_wh);
  // (3 z² − 4 z + 1)/2 = iωh z²  →  (3 − 2 iωh) z² − 4 z + 1 = 0.
  const std::complex<double> a = 3.0 - 2.0 * i_wh;
  const std::complex<double> root = std::sqrt(16.0 - 4.0 * a);
  return (4.0 + root) / (2.0 * a);
}

// The scheme, not the rod, sets the frequency and the decay: at ω₁h = 0.3 backward Euler runs
// the first mode 3 % slow and damps it at 0.14 ω₁, BDF2 runs it 3 % slow too and damps it at
// 0.0055 ω₁ — the theory of each scheme (a mode's amplification per step) for the rod's own ω₁,
// measured by position Verlet in the same test: frequencies to 0.1 %, decay rates to 0.5 % (BE,
// over 3 s, before the energy reaches the Newton tolerance) and 2 % (BDF2, over 7.5 s, after
// its backward-Euler start). Under backward Euler the energy never grows from one step to the
// next. Position Verlet's ω₁ lies within 3 % of Euler–Bernoulli's (the clamp holds the whole
// first element, l̂/L = 2.5 % of the rod, as in rod_statics_test).
TEST(RodImplicit, CantileverFrequencyAndNumericalDampingFollowTheSchemesTheory) {
  Rod reference(cantilever(RodIntegrator::kPositionVerlet, 5.0e-5));
  reference.add<FixedEnd>();
  start_first_mode(reference, 1e-3);
  const double omega = measure(reference, 2.0).frequency;
  const double euler_bernoulli = euler_bernoulli_first_mode(cantilever({}, 1.0));
  std::printf("first mode: %.5f rad/s (position Verlet), Euler-Bernoulli %.5f rad/s\n", omega,
              euler_bernoulli);
  EXPECT_NEAR(omega, euler_bernoulli, 0.03 * euler_bernoulli);

  for (RodIntegrator integrator : {RodIntegrator::kBackwardEuler, RodIntegrator::kBdf2}) {
    const bool bdf2 = integrator == RodIntegrator::kBdf2;
    const double h = 0.3 / omega;
    Rod rod(cantilever(integrator, h));
    rod.add<FixedEnd>();
    start_first_mode(rod, 1e-3);
    const Oscillation measured = bdf2 ? measure(rod, 8.0, 0.5) : measure(rod, 3.0);
    const std::complex<double> z = amplification(integrator, omega * h);
    const double frequency = std::arg(z) / h, decay = -std::log(std::abs(z)) / h;
    std::printf(
        "%s at ωh = 0.3: frequency %.5f rad/s (theory %.5f), decay %.5f 1/s (theory "
        "%.5f)\n",
        integrator_name(integrator), measured.frequency, frequency, measured.decay_rate, decay);
    EXPECT_NEAR(measured.frequency, frequency, 0.001 * frequency) << integrator_name(integrator);
    EXPECT_NEAR(measured.decay_rate, decay, (bdf2 ? 0.02 : 0.005) * decay)
        << integrator_name(integrator);
    if (!bdf2) EXPECT_TRUE(measured.energy_never_grew);
  }
}

// The equilibrium of an implicit step does not depend on its length: the Timoshenko cantilever
// of rod_statics_test settles to the same tip deflection (to 10⁻⁹ m) at steps 400 times apart,
// the longest ten times the ramp of its load, and to the closed form as position Verlet does.
TEST(RodImplicit, StaticsAreExactAtAnyStep) {
  const double force = 15.0, length = 3.0, radius = 0.25;
  const double area = std::numbers::pi * radius * radius;
  const double second_moment = std::numbers::pi * std::pow(radius, 4) / 4.0;
  const double expected = force * length / (4.0 / 3.0 * 1.0e4 * area) +
                          force * std::pow(length, 3) / (3.0 * 1.0e6 * second_moment);
  std::vector<double> deflections;
  for (RodIntegrator integrator : {RodIntegrator::kBackwardEuler, RodIntegrator::kBdf2}) {
    for (double h : {0.05, 1.0, 20.0}) {
      RodSpec spec;
      spec.n_elements = 100;
      spec.length = length;
      spec.radius = radius;
      spec.density = 1000.0;
      spec.youngs_modulus = 1.0e6;
      spec.shear_modulus = 1.0e4;
      spec.direction = Eigen::Vector3d::UnitZ();
      spec.normal = Eigen::Vector3d::UnitX();
      spec.time_step = h;
      spec.integrator = integrator;
      Rod rod(spec);
      rod.add<FixedEnd>();
      rod.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(-force, 0, 0), 2.0);
      add_uniform_damping(rod, 1.4);
      ASSERT_TRUE(rod.advance(static_cast<int>(std::ceil(2.0 / h))));
      ASSERT_TRUE(settle(rod, 2000.0, 1e-11));
      const double deflection = -rod.tip_position().x();
      std::printf("%s, step %.3g s: tip deflection %.9f m (closed form %.6f m), %lld steps\n",
                  integrator_name(integrator), h, deflection, expected,
                  static_cast<long long>(rod.newton_statistics().steps));
      EXPECT_NEAR(deflection, expected, 0.02 * expected);
      deflections.push_back(deflection);
    }
  }
  for (double deflection : deflections) EXPECT_NEAR(deflection, deflections.front(), 1e-9);
}

// Rigid translation (no internal loads) under the models' damping laws, closed form per step:
// backward Euler multiplies the velocity by 1/(1 + h c/m) every step.
TEST(RodImplicit, DampingLawsDecayARigidTranslationAsTheSchemePredicts) {
  for (bool internal : {true, false}) {
    RodSpec spec = cantilever(RodIntegrator::kBackwardEuler, 0.02);
    Rod rod(spec);
    const double area = std::numbers::pi * spec.radius * spec.radius;
    double rate;  // c/m, 1/s
    if (internal) {
      const double nu = 20.0;
      rod.add<InternalDamping>(nu);
      rate = nu / (spec.density * area);
    } else {
      rate = 3.0;
      add_uniform_damping(rod, rate);
    }
    rod.mutable_state().velocities.row(2).setConstant(0.5);
    rod.state_changed();
    ASSERT_TRUE(rod.advance(50));
    const double expected = 0.5 * std::pow(1.0 + spec.time_step * rate, -50);
    for (int j = 0; j <= rod.n_elements(); ++j) {
      EXPECT_NEAR(rod.state().velocities(2, j), expected, 1e-9 * 0.5) << "node " << j;
    }
    EXPECT_LT(expected, 0.5 * 0.3);  // the decay is substantial
  }
}

// Tip error against position Verlet at its own small step (3·10⁻⁷ m from Verlet at half that
// step), for a damped cantilever driven by a smooth tip force: halving the step halves backward
// Euler's error and quarters BDF2's. Newton's tolerance is tightened to 10⁻¹² here so that its
// error, which a step's velocity carries into the following ones, stays well below BDF2's
// 2·10⁻⁵ m at 5 ms.
TEST(RodImplicit, BackwardEulerIsFirstOrderAndBdf2SecondOrder) {
  auto run = [](RodIntegrator integrator, double h) {
    RodSpec spec = cantilever(integrator, h);
    spec.newton.tolerance = 1e-12;
    Rod rod(spec);
    rod.add<FixedEnd>();
    add_uniform_damping(rod, 2.0);
    rod.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.05, 0.02), 0.3);
    std::vector<Eigen::Vector3d> tips;
    for (int k = 0; k < 20; ++k) {
      EXPECT_TRUE(rod.advance(static_cast<int>(std::lround(0.04 / h))));
      tips.push_back(rod.tip_position());
    }
    return tips;
  };
  const std::vector<Eigen::Vector3d> reference = run(RodIntegrator::kPositionVerlet, 2.5e-5);
  auto error = [&](RodIntegrator integrator, double h) {
    const std::vector<Eigen::Vector3d> tips = run(integrator, h);
    double worst = 0.0;
    for (std::size_t k = 0; k < tips.size(); ++k) {
      worst = std::max(worst, (tips[k] - reference[k]).norm());
    }
    return worst;
  };
  for (RodIntegrator integrator : {RodIntegrator::kBackwardEuler, RodIntegrator::kBdf2}) {
    const double coarse = error(integrator, 0.01), fine = error(integrator, 0.005);
    const double order = std::log2(coarse / fine);
    std::printf("%s: tip error %.3e m at 10 ms, %.3e m at 5 ms: order %.2f\n",
                integrator_name(integrator), coarse, fine, order);
    const double expected = integrator == RodIntegrator::kBackwardEuler ? 1.0 : 2.0;
    EXPECT_NEAR(order, expected, 0.25) << integrator_name(integrator);
  }
}

TEST(RodImplicit, NewtonFailureRaisesAnErrorAndLeavesTheRodAtTheStepsStart) {
  RodSpec spec = cantilever(RodIntegrator::kBackwardEuler, 0.5);
  spec.newton.max_iterations = 2;
  spec.newton.max_halvings = 0;
  spec.newton.tolerance = 1e-14;
  Rod rod(spec);
  rod.add<FixedEnd>();
  rod.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 3.0, 1.0));
  const RodState before = rod.state();
  const std::string message = tendril::testing::error_message([&] { (void)rod.advance(1); });
  EXPECT_NE(message.find("Newton's method did not converge in 2 iterations"), std::string::npos)
      << message;
  EXPECT_NE(message.find("backward_euler"), std::string::npos) << message;
  EXPECT_EQ(rod.state().positions, before.positions);
  EXPECT_EQ(rod.state().directors, before.directors);
  EXPECT_EQ(rod.state().velocities, before.velocities);
  EXPECT_EQ(rod.time(), 0.0);
  EXPECT_EQ(rod.newton_statistics().halvings, 0);
}

// With halvings allowed, a step that fails (a sudden tip load with at most 6 iterations: the
// first 1/16 of the step is the longest that converges) is taken in pieces and reported as
// such; the pieces land at the step's end.
TEST(RodImplicit, AFailedStepIsTakenAgainInHalves) {
  RodSpec spec = cantilever(RodIntegrator::kBackwardEuler, 0.5);
  spec.newton.max_iterations = 6;
  spec.newton.max_halvings = 8;
  Rod rod(spec);
  rod.add<FixedEnd>();
  rod.add<EndForces>(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.03, 0.0));
  ASSERT_TRUE(rod.advance(1));
  const NewtonStatistics statistics = rod.newton_statistics();
  std::printf("one 0.5 s step: %lld halvings, %lld steps\n",
              static_cast<long long>(statistics.halvings),
              static_cast<long long>(statistics.steps));
  EXPECT_GE(statistics.halvings, 4);
  EXPECT_EQ(statistics.steps, statistics.halvings + 1);  // each halving adds one step
  EXPECT_NEAR(rod.time(), 0.5, 1e-15);
}

TEST(RodImplicit, AdvanceByIsForImplicitRodsOnly) {
  Rod verlet(cantilever(RodIntegrator::kPositionVerlet, 1e-4));
  EXPECT_THROW((void)verlet.advance_by(0.01, 2), Error);
  Rod implicit(cantilever(RodIntegrator::kBdf2, 0.01));
  implicit.add<FixedEnd>();
  implicit.add<Gravity>();
  ASSERT_TRUE(implicit.advance_by(0.063, 7));
  EXPECT_NEAR(implicit.time(), 0.063, 1e-15);
  EXPECT_THROW((void)implicit.advance_by(-1.0, 2), Error);
}

// Case 3's arm (rate-limited muscles, contact) and a plain rod, each integrator: stepping on
// from a loaded snapshot repeats the original bit for bit — BDF2's previous step included.
TEST(RodImplicit, SnapshotsRepeatBitForBit) {
  for (RodIntegrator integrator : {RodIntegrator::kBackwardEuler, RodIntegrator::kBdf2}) {
    ElasticaArmSpec spec = ElasticaArmSpec::structured_obstacles();
    spec.integrator = integrator;
    auto build = [&] {
      ElasticaArm arm = build_elastica_arm(spec);
      Eigen::VectorXd targets(2);
      targets << 0.9, -0.7;
      arm.muscles->set_targets(targets);
      return arm;
    };
    ElasticaArm original = build();
    ASSERT_TRUE(original.rod.advance(40));
    Snapshot bytes;
    SnapshotWriter out(bytes);
    original.rod.save_state(out);
    ElasticaArm copy = build();
    SnapshotReader in(bytes);
    copy.rod.load_state(in);
    EXPECT_TRUE(in.at_end());
    ASSERT_TRUE(original.rod.advance(30));
    ASSERT_TRUE(copy.rod.advance(30));
    EXPECT_EQ(copy.rod.state().positions, original.rod.state().positions);
    EXPECT_EQ(copy.rod.state().velocities, original.rod.state().velocities);
    EXPECT_EQ(copy.rod.state().directors, original.rod.state().directors);
    EXPECT_EQ(copy.rod.state().angular_velocities, original.rod.state().angular_velocities);
    EXPECT_EQ(copy.rod.time(), original.rod.time());
  }
}

}  // namespace
}  // namespace tendril::physics
