// The lattice beam against beam theory. Its homogenized stiffness, for cell size a = 0.025 m
// and spring stiffness k = 18750 N/m:
//   bending  EI = k a · 2a²  (the two outer columns, axial stiffness k a at ±a)
//              + k a³ / 4   (the diagonals, whose strain is half the column strain at the
//                            middle of their cell once the rows contract freely)  = 0.659 N·m²,
//   shear    GA = 2 k a      (the crossed diagonals of the two cells across)     = 937.5 N,
//   mass     μ  = 60 kg/m² × 0.05 m = 3 kg/m.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tendril/physics/lattice/beam_lattice.hpp"
#include "tendril/physics/lattice/node_forces.hpp"

namespace tendril::physics {
namespace {

constexpr double kCell = 0.025, kSpring = 18750.0, kLength = 0.75;
constexpr double kBending =
    kSpring * kCell * 2.0 * kCell * kCell + kSpring * kCell * kCell * kCell / 4.0;
constexpr double kShear = 2.0 * kSpring * kCell;
constexpr double kMassPerLength = 60.0 * 0.05;

// Runs until the kinetic energy is below `tolerance` J (a settled state), at most `seconds`.
bool settle(Lattice& lattice, double seconds, double tolerance) {
  const int chunk = std::max(1, static_cast<int>(std::lround(0.1 / lattice.numerics().time_step)));
  while (lattice.time() < seconds) {
    if (!lattice.advance(chunk)) return false;
    if (lattice.kinetic_energy() < tolerance) return true;
  }
  return false;
}

// Cantilever under a transverse tip load P (Timoshenko): δ = P L³/(3 EI) + P L/(GA). The
// lattice is 0.45 % stiffer (the clamped base row cannot contract); 1 % tolerance. The implicit
// steps stop exactly on the static equilibrium (at rest their update is f(x) = 0), so the
// settled deflection is the same for every step size.
TEST(BeamStatics, CantileverTipDeflectionUnderATipLoad) {
  const double load = 0.05;  // N, small: δ ≈ 1.4 % of L
  const double expected = load * std::pow(kLength, 3) / (3.0 * kBending) + load * kLength / kShear;
  double first = 0.0;
  for (const auto& [integrator, step] : {std::pair{LatticeIntegrator::kBackwardEuler, 0.05},
                                         std::pair{LatticeIntegrator::kBdf2, 0.01},
                                         std::pair{LatticeIntegrator::kBackwardEuler, 0.002}}) {
    BeamLatticeSpec spec;
    spec.mass_damping = 5.0;
    spec.numerics = LatticeNumerics{integrator, step, 1};
    BeamLattice beam(spec);
    auto& tip = beam.lattice().add<NodeForces>();
    tip.forces()(0, spec.node(30, 0)) = 0.25 * load;
    tip.forces()(0, spec.node(30, 1)) = 0.5 * load;
    tip.forces()(0, spec.node(30, 2)) = 0.25 * load;
    ASSERT_TRUE(settle(beam.lattice(), 60.0, 1e-16)) << step;
    const double deflection = beam.tip_position().x();
    EXPECT_NEAR(deflection, expected, 0.01 * expected) << step;
    if (first == 0.0) first = deflection;
    EXPECT_NEAR(deflection, first, 1e-8) << step;  // 1e-6 relative: settled to 1e-16 J
  }
}

// A couple τ on row 29 (y = 0.725 m) bends everything below it at the uniform curvature τ/EI:
// the row turns by θ = τ y / EI and the unwrapped row angle reads it.
TEST(BeamStatics, CoupleBendsAtUniformCurvature) {
  BeamLatticeSpec spec;
  spec.mass_damping = 5.0;
  BeamLattice beam(spec);
  const double torque = 0.05;  // N·m
  Eigen::VectorXd torques = Eigen::VectorXd::Zero(5);
  torques[4] = torque;
  beam.couples().set_torques(torques);
  ASSERT_TRUE(settle(beam.lattice(), 60.0, 1e-16));
  const double expected = torque * 0.725 / kBending;
  EXPECT_NEAR(beam.row_angle(29), expected, 0.01 * expected);
  // Counter-clockwise positive: the beam bends towards −x.
  EXPECT_LT(beam.tip_position().x(), 0.0);
  // Rows above the couple carry no moment and stay straight relative to it.
  EXPECT_NEAR(beam.row_angle(30), beam.row_angle(29), 1e-3 * expected);
}

TEST(BeamStatics, RowAngleUnwrapsPastHalfATurn) {
  // 4.5 N·m at the tip curls the beam past π (κ ≈ 6.8 m⁻¹ over 0.725 m ≈ 4.9 rad).
  BeamLattice beam(BeamLatticeSpec{});
  Eigen::VectorXd torques = Eigen::VectorXd::Zero(5);
  torques[4] = 4.5;
  beam.couples().set_torques(torques);
  ASSERT_TRUE(beam.lattice().advance(800));  // 8 s
  EXPECT_GT(beam.row_angle(29), std::numbers::pi);
  EXPECT_LT(beam.row_angle(29), 2.0 * std::numbers::pi);
}

// First bending mode of a clamped–free beam: ω₁ = 1.8751² √(EI / (μ L⁴)) = 2.930 rad/s. The
// lattice oscillates 0.5 % slower (shear flexibility, lumped masses); 1.5 % tolerance. Explicit
// reference, undamped, released from the static shape under a tip load (mostly mode 1).
TEST(BeamStatics, FirstBendingFrequency) {
  BeamLatticeSpec preload;
  preload.mass_damping = 5.0;
  BeamLattice bent(preload);
  auto& tip = bent.lattice().add<NodeForces>();
  tip.forces()(0, preload.node(30, 1)) = 0.05;
  ASSERT_TRUE(settle(bent.lattice(), 60.0, 1e-16));

  BeamLatticeSpec spec;
  spec.mass_damping = 0.0;
  spec.stiffness_damping = 0.0;
  spec.numerics = LatticeNumerics{LatticeIntegrator::kSymplecticEuler, 1.0e-4, 1};
  BeamLattice beam(spec);
  LatticeState start = bent.lattice().state();
  start.time = 0.0;
  beam.lattice().set_state(start);
  std::vector<double> crossings;
  double previous = beam.tip_position().x();
  while (crossings.size() < 4) {
    ASSERT_TRUE(beam.lattice().advance(1));
    const double now = beam.tip_position().x();
    if (previous > 0.0 && now <= 0.0) crossings.push_back(beam.lattice().time());
    previous = now;
    ASSERT_LT(beam.lattice().time(), 20.0);
  }
  const double omega = 2.0 * std::numbers::pi * 3.0 / (crossings[3] - crossings[0]);
  const double expected =
      1.8751 * 1.8751 * std::sqrt(kBending / (kMassPerLength * std::pow(kLength, 4)));
  EXPECT_NEAR(omega, expected, 0.015 * expected);
}

}  // namespace
}  // namespace tendril::physics
