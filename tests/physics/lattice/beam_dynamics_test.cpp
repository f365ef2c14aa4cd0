// The implicit steps against the explicit reference; energy without damping; blow-ups;
// snapshots.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "support/error_message.hpp"
#include "tendril/physics/lattice/beam_lattice.hpp"
#include "tendril/physics/lattice/node_forces.hpp"

namespace tendril::physics {
namespace {

BeamLatticeSpec with(LatticeIntegrator integrator, double time_step) {
  BeamLatticeSpec spec;
  spec.numerics = LatticeNumerics{integrator, time_step, 1};
  return spec;
}

// Tip positions every 50 ms over 2 s after a 1 N·m couple is switched on at row 29 (the tip
// swings 0.5 m and the step excites every mode).
std::vector<Eigen::Vector2d> couple_step_response(const BeamLatticeSpec& spec) {
  BeamLattice beam(spec);
  Eigen::VectorXd torques = Eigen::VectorXd::Zero(5);
  torques[4] = 1.0;
  beam.couples().set_torques(torques);
  const int per_period = static_cast<int>(std::lround(0.05 / spec.numerics.time_step));
  std::vector<Eigen::Vector2d> tips;
  for (int period = 0; period < 40; ++period) {
    EXPECT_TRUE(beam.lattice().advance(per_period));
    tips.push_back(beam.tip_position());
  }
  return tips;
}

double worst_gap(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm());
  return worst;
}

// The explicit reference at 0.1 ms (itself within 0.1 mm of 25 µs). BDF2 converges on it at
// second order and is within 1 cm at the tasks' 10 ms; backward Euler at first order, 2.5 cm.
TEST(BeamDynamics, ImplicitStepsConvergeOnTheExplicitReference) {
  const auto reference = couple_step_response(with(LatticeIntegrator::kSymplecticEuler, 1.0e-4));
  EXPECT_GT(std::abs(reference[10].x()), 0.3);  // it moved

  const double bdf2_10 =
      worst_gap(couple_step_response(with(LatticeIntegrator::kBdf2, 0.01)), reference);
  const double bdf2_5 =
      worst_gap(couple_step_response(with(LatticeIntegrator::kBdf2, 0.005)), reference);
  const double bdf2_2 =
      worst_gap(couple_step_response(with(LatticeIntegrator::kBdf2, 0.0025)), reference);
  EXPECT_LT(bdf2_10, 0.01);
  EXPECT_GT(bdf2_10 / bdf2_5, 2.5);  // second order: 4 in the limit
  EXPECT_GT(bdf2_5 / bdf2_2, 3.0);
  const double euler_10 =
      worst_gap(couple_step_response(with(LatticeIntegrator::kBackwardEuler, 0.01)), reference);
  const double euler_5 =
      worst_gap(couple_step_response(with(LatticeIntegrator::kBackwardEuler, 0.005)), reference);
  EXPECT_LT(euler_10, 0.03);
  EXPECT_NEAR(euler_10 / euler_5, 2.0, 0.5);  // first order
  EXPECT_LT(bdf2_10, euler_10);
}

// More Newton iterations barely move the step: one iteration from the predictor is within
// 5 mm (4.2 mm measured) of the converged step while the tip swings 0.5 m.
TEST(BeamDynamics, OneNewtonIterationIsCloseToTheConvergedStep) {
  BeamLatticeSpec converged = with(LatticeIntegrator::kBdf2, 0.01);
  converged.numerics.newton_iterations = 4;
  EXPECT_LT(worst_gap(couple_step_response(with(LatticeIntegrator::kBdf2, 0.01)),
                      couple_step_response(converged)),
            0.005);
}

// Without damping, symplectic Euler keeps the total energy of the released beam within a
// narrow band (0.03 % measured; 0.1 % allowed) over 10⁵ steps — no drift.
TEST(BeamDynamics, ExplicitEnergyIsBoundedWithoutDamping) {
  BeamLatticeSpec spec = with(LatticeIntegrator::kSymplecticEuler, 1.0e-4);
  spec.mass_damping = 0.0;
  spec.stiffness_damping = 0.0;
  BeamLattice beam(spec);
  auto& tip = beam.lattice().add<NodeForces>();
  tip.forces()(0, spec.node(30, 1)) = 0.5;
  ASSERT_TRUE(beam.lattice().advance(3000));  // loaded: a deformed, moving state
  tip.forces().setZero();
  const double start = beam.lattice().kinetic_energy() + beam.lattice().elastic_energy();
  ASSERT_GT(start, 1e-4);
  double low = start, high = start;
  for (int chunk = 0; chunk < 1000; ++chunk) {
    ASSERT_TRUE(beam.lattice().advance(100));
    const double energy = beam.lattice().kinetic_energy() + beam.lattice().elastic_energy();
    low = std::min(low, energy);
    high = std::max(high, energy);
  }
  EXPECT_LT((high - low) / start, 1e-3);
}

// With damping the energy only falls (backward Euler is dissipative on top).
TEST(BeamDynamics, DampedEnergyDecays) {
  BeamLattice beam(with(LatticeIntegrator::kBackwardEuler, 0.01));
  auto& tip = beam.lattice().add<NodeForces>();
  tip.forces()(0, 91) = 0.5;
  ASSERT_TRUE(beam.lattice().advance(50));
  tip.forces().setZero();
  double previous = beam.lattice().kinetic_energy() + beam.lattice().elastic_energy();
  for (int step = 0; step < 300; ++step) {
    ASSERT_TRUE(beam.lattice().advance(1));
    const double energy = beam.lattice().kinetic_energy() + beam.lattice().elastic_energy();
    EXPECT_LE(energy, previous * (1.0 + 1e-12)) << step;
    previous = energy;
  }
}

// The largest torques of the ellipse task, all one way, for 5 s: far beyond what a lattice
// without bending springs carries (40 N·m at the base would compress the outer column by
// κ a = 40/0.659 × 0.025 ≈ 150 %), so cells turn inside out, but every integrator stays finite
// and says so.
TEST(BeamDynamics, ExtremeTorquesStayFinite) {
  for (const auto& spec :
       {with(LatticeIntegrator::kBdf2, 0.01), with(LatticeIntegrator::kBackwardEuler, 0.05),
        with(LatticeIntegrator::kSymplecticEuler, 2.5e-4)}) {
    BeamLattice beam(spec);
    beam.couples().set_torques(Eigen::VectorXd::Constant(5, 8.0));
    EXPECT_TRUE(
        beam.lattice().advance(static_cast<int>(std::lround(5.0 / spec.numerics.time_step))));
    EXPECT_GT(beam.inverted_cells(), 0);
  }
}

// A moderate couple (1 N·m on every torque row, 5 N·m at the base: outer columns compressed
// by ≈ 19 %) bends the beam without turning any cell inside out.
TEST(BeamDynamics, ModerateTorquesInvertNoCell) {
  BeamLattice beam(BeamLatticeSpec{});
  EXPECT_EQ(beam.inverted_cells(), 0);
  beam.couples().set_torques(Eigen::VectorXd::Constant(5, 1.0));
  for (int period = 0; period < 100; ++period) {
    ASSERT_TRUE(beam.lattice().advance(5));
    ASSERT_EQ(beam.inverted_cells(), 0) << period;
  }
  EXPECT_GT(beam.row_angle(30), 1.0);
}

TEST(BeamDynamics, InvertedCellsAreCounted) {
  BeamLattice beam(BeamLatticeSpec{});
  LatticeState state = beam.lattice().state();
  for (int node = 90; node < 93; ++node) state.positions(1, node) = 0.70;  // tip row below row 29
  beam.lattice().set_state(state);
  EXPECT_EQ(beam.inverted_cells(), 2);  // the two quads below it
}

TEST(BeamDynamics, NonFiniteStateIsReportedUntilANewStateIsSet) {
  for (const auto integrator : {LatticeIntegrator::kBdf2, LatticeIntegrator::kSymplecticEuler}) {
    BeamLattice beam(with(integrator, integrator == LatticeIntegrator::kBdf2 ? 0.01 : 1e-4));
    ASSERT_TRUE(beam.lattice().advance(3));
    LatticeState state = beam.lattice().state();
    const LatticeState good = state;
    state.velocities(1, 50) = std::numeric_limits<double>::quiet_NaN();
    beam.lattice().set_state(state);
    EXPECT_FALSE(beam.lattice().state_is_finite());
    EXPECT_FALSE(beam.lattice().advance(1));
    EXPECT_FALSE(beam.lattice().advance(1)) << "a blown-up lattice stays reported";
    beam.lattice().set_state(good);
    EXPECT_TRUE(beam.lattice().advance(1));
  }
}

TEST(BeamDynamics, OverflowingTorqueIsABlowUp) {
  BeamLattice beam(BeamLatticeSpec{});
  beam.couples().set_torques(Eigen::VectorXd::Constant(5, 1e300));
  EXPECT_FALSE(beam.lattice().advance(5));
}

TEST(BeamDynamics, SteppingOnFromALoadedSnapshotRepeatsTheOriginalBitForBit) {
  for (const auto integrator : {LatticeIntegrator::kBdf2, LatticeIntegrator::kSymplecticEuler}) {
    const BeamLatticeSpec spec =
        with(integrator, integrator == LatticeIntegrator::kBdf2 ? 0.01 : 1e-4);
    BeamLattice original(spec);
    Eigen::VectorXd torques(5);
    torques << 1.0, -2.0, 0.5, 3.0, -1.0;
    original.couples().set_torques(torques);
    ASSERT_TRUE(original.lattice().advance(17));
    Snapshot bytes;
    SnapshotWriter out(bytes);
    original.lattice().save_state(out);

    BeamLattice copy(spec);
    ASSERT_TRUE(copy.lattice().advance(3));  // another history entirely
    SnapshotReader in(bytes);
    copy.lattice().load_state(in);
    EXPECT_TRUE(in.at_end());
    EXPECT_EQ(copy.couples().torques(), torques);
    ASSERT_TRUE(original.lattice().advance(23));
    ASSERT_TRUE(copy.lattice().advance(23));
    EXPECT_EQ(copy.lattice().state().positions, original.lattice().state().positions);
    EXPECT_EQ(copy.lattice().state().velocities, original.lattice().state().velocities);
    EXPECT_EQ(copy.lattice().time(), original.lattice().time());
  }
}

TEST(BeamDynamics, ASnapshotOfAnotherLatticeIsRefusedAndChangesNothing) {
  BeamLatticeSpec small;
  small.rows = 11;
  small.torque_rows = {5, 10};
  BeamLattice other(small);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  other.lattice().save_state(out);

  BeamLattice beam(BeamLatticeSpec{});
  beam.couples().set_torques(Eigen::VectorXd::Constant(5, 1.0));
  ASSERT_TRUE(beam.lattice().advance(4));
  const LatticeState before = beam.lattice().state();
  SnapshotReader in(bytes);
  EXPECT_NE(testing::error_message([&] { beam.lattice().load_state(in); }), "no error");
  EXPECT_EQ(beam.lattice().state().positions, before.positions);
  EXPECT_EQ(beam.couples().torques(), Eigen::VectorXd::Constant(5, 1.0));
}

}  // namespace
}  // namespace tendril::physics
