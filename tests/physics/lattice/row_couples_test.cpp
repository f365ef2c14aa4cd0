// A row couple is a pure couple: zero net force and a moment of exactly τ, whatever the row's
// current length and orientation.
#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/physics/lattice/beam_lattice.hpp"

namespace tendril::physics {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

TEST(RowCouples, ZeroNetForceAndTheSetMomentAboutAnyPoint) {
  const LatticeModel model = build_beam_model(BeamLatticeSpec{});
  RowCouples couples({{15, 17}, {33, 35}, {51, 53}, {69, 71}, {87, 89}});
  couples.attach(model);
  Eigen::VectorXd torques(5);
  torques << 4.5, -3.0, 0.7, -4.5, 2.25;
  couples.set_torques(torques);
  // A deformed, rotated, stretched configuration.
  Rng rng(5);
  Eigen::Matrix2Xd positions = model.rest_positions;
  for (int i = 0; i < positions.cols(); ++i) {
    positions.col(i) += Eigen::Vector2d(rng.uniform(-0.01, 0.01), rng.uniform(-0.01, 0.01));
  }
  Eigen::Matrix2Xd forces = Eigen::Matrix2Xd::Zero(2, model.n_nodes());
  couples.add_forces(model, positions, forces);

  EXPECT_LT(forces.rowwise().sum().norm(), 1e-12);
  for (const Eigen::Vector2d& point : {Eigen::Vector2d(0, 0), Eigen::Vector2d(3.0, -7.0)}) {
    double moment = 0.0;
    for (int i = 0; i < model.n_nodes(); ++i)
      moment += cross(positions.col(i) - point, forces.col(i));
    EXPECT_NEAR(moment, torques.sum(), 1e-12);
  }
  // Each couple by itself, and the middle node of a row gets nothing.
  for (int k = 0; k < 5; ++k) {
    const auto [left, right] = couples.pairs()[k];
    EXPECT_LT((forces.col(left) + forces.col(right)).norm(), 1e-12);
    EXPECT_NEAR(cross(positions.col(right) - positions.col(left), forces.col(right)), torques[k],
                1e-12);
    EXPECT_EQ(forces.col(left + 1), Eigen::Vector2d::Zero());
  }
}

// On a free lattice (nothing fixed, no mass damping) every internal force is central, so the
// angular momentum Σ m x × v grows at exactly τ and the momentum stays zero while the body
// turns through more than a full revolution; symplectic Euler keeps this exactly:
// L₊ = Σ m (x + h v₊) × v₊ = L + h Σ x × F.
TEST(RowCouples, AFreeBodySpinsUpAtTheAppliedTorque) {
  LatticeModel model;
  model.rest_positions.resize(2, 4);
  model.rest_positions << 0.0, 0.1, 0.0, 0.1, 0.0, 0.0, 0.1, 0.1;
  model.masses = Eigen::Vector4d(0.1, 0.2, 0.3, 0.4);
  model.fixed = {0, 0, 0, 0};
  const double k = 5000.0, c = 2.0;
  for (auto [a, b] : {std::pair{0, 1}, {2, 3}, {0, 2}, {1, 3}, {0, 3}, {1, 2}}) {
    model.springs.push_back(
        Spring{a, b, (model.rest_positions.col(b) - model.rest_positions.col(a)).norm(), k, c});
  }
  Lattice lattice(model, LatticeNumerics{LatticeIntegrator::kSymplecticEuler, 1.0e-4, 1});
  auto& couples = lattice.add<RowCouples>(std::vector<RowCouples::Pair>{{0, 1}});
  const double torque = 0.02;  // N·m
  couples.set_torques(Eigen::VectorXd::Constant(1, torque));
  // 4 s, following the pair's direction to count the turns.
  const auto direction = [&] {
    const Eigen::Vector2d across =
        lattice.state().positions.col(1) - lattice.state().positions.col(0);
    return std::atan2(across.y(), across.x());
  };
  double turned = 0.0, previous = direction();
  for (int chunk = 0; chunk < 400; ++chunk) {
    ASSERT_TRUE(lattice.advance(100));
    turned += std::remainder(direction() - previous, 2.0 * 3.141592653589793);
    previous = direction();
  }

  const LatticeState& state = lattice.state();
  double angular_momentum = 0.0;
  Eigen::Vector2d momentum = Eigen::Vector2d::Zero();
  for (int i = 0; i < 4; ++i) {
    angular_momentum += model.masses[i] * cross(state.positions.col(i), state.velocities.col(i));
    momentum += model.masses[i] * state.velocities.col(i);
  }
  EXPECT_NEAR(angular_momentum, torque * lattice.time(), 1e-9);
  EXPECT_LT(momentum.norm(), 1e-12);
  EXPECT_GT(turned, 2.0 * 3.141592653589793);  // a follower couple: it kept turning the body
}

TEST(RowCouples, TorquesOfTheWrongSizeOrNotFiniteAreRefused) {
  RowCouples couples({{0, 2}});
  EXPECT_THROW(couples.set_torques(Eigen::Vector2d(1.0, 2.0)), Error);
  EXPECT_THROW(couples.set_torques(Eigen::VectorXd::Constant(1, std::nan(""))), Error);
  const LatticeModel model = build_beam_model(BeamLatticeSpec{});
  RowCouples outside({{0, 93}});
  EXPECT_THROW(outside.attach(model), Error);
}

}  // namespace
}  // namespace tendril::physics
