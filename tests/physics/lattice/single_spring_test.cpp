// Each integrator on the simplest lattice, one mass on one spring, against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tendril/physics/lattice/lattice.hpp"

namespace tendril::physics {
namespace {

constexpr double kMass = 0.5;         // kg
constexpr double kStiffness = 200.0;  // N/m, ω = 20 rad/s
constexpr double kRest = 1.0;         // m

// Node 0 fixed at the origin, node 1 at x = rest + stretch; motion stays on the x axis.
Lattice spring(LatticeIntegrator integrator, double time_step, double stretch) {
  LatticeModel model;
  model.rest_positions = Eigen::Matrix2Xd::Zero(2, 2);
  model.rest_positions(0, 1) = kRest;
  model.masses = Eigen::Vector2d(1.0, kMass);
  model.fixed = {1, 0};
  model.springs = {Spring{0, 1, kRest, kStiffness, 0.0}};
  Lattice lattice(model, LatticeNumerics{integrator, time_step, 1});
  LatticeState state = lattice.state();
  state.positions(0, 1) += stretch;
  lattice.set_state(state);
  return lattice;
}

double stretch(const Lattice& lattice) { return lattice.state().positions(0, 1) - kRest; }
double speed(const Lattice& lattice) { return lattice.state().velocities(0, 1); }

// Symplectic Euler: the period of x'' = −ω² x is 2π/ω to O(h²) (its discrete frequency is
// 2 asin(ωh/2)/h), and the energy oscillates by O(ωh) without drifting.
TEST(SingleSpring, SymplecticEulerOscillatesAtTheSpringsFrequency) {
  const double omega = std::sqrt(kStiffness / kMass);
  const double h = 1.0e-4;
  Lattice lattice = spring(LatticeIntegrator::kSymplecticEuler, h, 0.01);
  const double energy = 0.5 * kStiffness * 0.01 * 0.01;
  double previous = stretch(lattice);
  std::vector<double> downward_crossings;
  double worst_energy_error = 0.0;
  for (int step = 0; step < 200000; ++step) {
    ASSERT_TRUE(lattice.advance());
    const double now = stretch(lattice);
    if (previous > 0.0 && now <= 0.0) {
      // Linear interpolation of the crossing time within the step.
      downward_crossings.push_back(lattice.time() - h * now / (now - previous));
    }
    previous = now;
    const double total = lattice.kinetic_energy() + lattice.elastic_energy();
    worst_energy_error = std::max(worst_energy_error, std::abs(total / energy - 1.0));
  }
  ASSERT_GE(downward_crossings.size(), 60u);
  const double period = (downward_crossings.back() - downward_crossings.front()) /
                        static_cast<double>(downward_crossings.size() - 1);
  EXPECT_NEAR(period, 2.0 * std::numbers::pi / omega, 1e-6 * period);
  EXPECT_LT(worst_energy_error, omega * h);  // bounded by ωh = 2e-3, no drift over 634 periods
  const double late_energy = lattice.kinetic_energy() + lattice.elastic_energy();
  EXPECT_NEAR(late_energy / energy, 1.0, omega * h);
}

// Backward Euler on x'' = −ω² x is linear, so one Newton iteration solves each step exactly:
//   x₊ = (x + h v)/(1 + ω²h²),  v₊ = (v − hω² x)/(1 + ω²h²),
// which shrinks ω²x² + v² by exactly 1/(1 + ω²h²) per step and turns the phase by atan(ωh).
TEST(SingleSpring, BackwardEulerDampsAndTurnsAsItsClosedForm) {
  const double omega = std::sqrt(kStiffness / kMass);
  const double h = 0.01;
  Lattice lattice = spring(LatticeIntegrator::kBackwardEuler, h, 0.01);
  const auto invariant = [&] {
    return omega * omega * stretch(lattice) * stretch(lattice) + speed(lattice) * speed(lattice);
  };
  const auto phase = [&] { return std::atan2(-speed(lattice), omega * stretch(lattice)); };
  const double start = invariant();
  const int steps = 37;
  ASSERT_TRUE(lattice.advance(steps));
  EXPECT_NEAR(invariant() / start, std::pow(1.0 + omega * omega * h * h, -steps), 1e-12);
  // Unwrapped: 37 × atan(0.2) = 7.31 rad.
  const double turned = steps * std::atan(omega * h);
  const double wrapped = std::remainder(turned, 2.0 * std::numbers::pi);
  EXPECT_NEAR(phase(), wrapped, 1e-10);
}

// BDF2 converges at second order, backward Euler at first: the error at t = 1 s against the
// exact cos(ωt) falls by ≈ 4 and ≈ 2 per halving of the step.
TEST(SingleSpring, Bdf2IsSecondOrderAndBackwardEulerFirst) {
  const double omega = std::sqrt(kStiffness / kMass);
  const auto error = [&](LatticeIntegrator integrator, double h) {
    Lattice lattice = spring(integrator, h, 0.01);
    EXPECT_TRUE(lattice.advance(static_cast<int>(std::lround(1.0 / h))));
    return std::abs(stretch(lattice) - 0.01 * std::cos(omega * lattice.time()));
  };
  for (const auto& [integrator, order] : {std::pair{LatticeIntegrator::kBdf2, 2.0},
                                          std::pair{LatticeIntegrator::kBackwardEuler, 1.0}}) {
    const double coarse = error(integrator, 1.0e-3);
    const double fine = error(integrator, 5.0e-4);
    EXPECT_NEAR(std::log2(coarse / fine), order, 0.15) << static_cast<int>(integrator);
  }
}

// Mass damping alone on a free node: backward Euler gives v₊ = v / (1 + αh) exactly.
TEST(SingleSpring, MassDampingDecaysAsBackwardEulersClosedForm) {
  LatticeModel model;
  model.rest_positions = Eigen::Matrix2Xd::Zero(2, 1);
  model.masses = Eigen::VectorXd::Constant(1, 0.3);
  model.fixed = {0};
  model.mass_damping = 2.0;
  Lattice lattice(model, LatticeNumerics{LatticeIntegrator::kBackwardEuler, 0.05, 1});
  LatticeState state = lattice.state();
  state.velocities.col(0) = Eigen::Vector2d(1.0, -2.0);
  lattice.set_state(state);
  ASSERT_TRUE(lattice.advance(10));
  const double factor = std::pow(1.0 + 2.0 * 0.05, -10);
  EXPECT_NEAR(lattice.state().velocities(0, 0), factor, 1e-14);
  EXPECT_NEAR(lattice.state().velocities(1, 0), -2.0 * factor, 1e-14);
}

}  // namespace
}  // namespace tendril::physics
