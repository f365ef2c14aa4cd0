#include "tendril/physics/forcing/active_strain.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "rod_test_support.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/internal_loads.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

using testing::ConstantActiveStrain;

RodSpec soft_rod(int n) {
  RodSpec spec;
  spec.n_elements = n;
  spec.length = 0.5;
  spec.radius = 0.02;
  spec.youngs_modulus = 1.0e6;
  spec.shear_modulus = 1.0e6 / 3.0;
  spec.time_step = 1.0e-4;
  return spec;
}

// Shifting the rest curvature is what the loads stand for, so a straight rod with κ̂ = 0 and an
// active curvature δκ must move exactly as a rod built with κ̂ = δκ (up to rounding: the two
// sum the same terms in another order).
TEST(ActiveStrain, ActiveCurvatureMovesTheRodAsARestCurvatureDoes) {
  const int n = 12;
  const Eigen::Vector3d kappa(1.5, -0.8, 0.4);  // 1/m about d1, d2, d3
  RodSpec curved = soft_rod(n);
  curved.rest_curvature = kappa;
  Rod reference(curved);
  reference.add<FixedEnd>();
  Rod active(soft_rod(n));
  active.add<FixedEnd>();
  Vectors curvature(3, n - 1);
  curvature.colwise() = kappa;
  active.add<ConstantActiveStrain>(Vectors::Zero(3, n), curvature);

  ASSERT_TRUE(reference.advance(3000));
  ASSERT_TRUE(active.advance(3000));
  // The tip has moved by centimetres (the rod curls up); the two agree to rounding.
  EXPECT_GT((reference.tip_position() - Eigen::Vector3d(0, 0.5, 0)).norm(), 0.01);
  EXPECT_LT((reference.state().positions - active.state().positions).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((reference.state().directors - active.state().directors).cwiseAbs().maxCoeff(), 1e-9);
}

// An active axial strain ε on a free-standing rod (clamped at one end, no other load) settles at
// the length (1 + ε) L: the elastic stress S(σ − ε) vanishes there.
TEST(ActiveStrain, ActiveStretchSettlesAtTheStretchedLength) {
  const int n = 10;
  const double epsilon = 0.08;
  Rod rod(soft_rod(n));
  rod.add<FixedEnd>();
  Vectors stretch = Vectors::Zero(3, n);
  stretch.row(2).setConstant(epsilon);
  rod.add<ConstantActiveStrain>(stretch, Vectors::Zero(3, n - 1));
  testing::add_uniform_damping(rod, 50.0);
  ASSERT_TRUE(testing::settle(rod, 5.0, 1e-8));
  EXPECT_NEAR(rod.tip_position().y(), 0.5 * (1.0 + epsilon), 1e-9);
  EXPECT_NEAR(rod.tip_position().x(), 0.0, 1e-12);
  EXPECT_NEAR(rod.tip_position().z(), 0.0, 1e-12);
}

// Net force and moment about the origin of the loads in `state` (node forces, and element
// couples taken to the lab frame), and the largest single couple.
struct Resultant {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double largest_couple = 0.0;
};

Resultant active_strain_resultant(const Rod& rod, const Vectors& stretch,
                                  const Vectors& curvature) {
  RodState scratch = rod.state();
  compute_internal_loads(rod.model(), scratch);
  scratch.external_forces.setZero();
  scratch.external_torques.setZero();
  ActiveStrainLoads loads;
  loads.resize(rod.model());
  loads.add(rod.model(), scratch, stretch, curvature);
  Resultant total;
  for (int j = 0; j <= rod.n_elements(); ++j) {
    const Eigen::Vector3d f = scratch.external_forces.col(j);
    total.force += f;
    total.moment += Eigen::Vector3d(scratch.positions.col(j)).cross(f);
  }
  for (int i = 0; i < rod.n_elements(); ++i) {
    const Eigen::Vector3d couple = scratch.external_torques.col(i);
    total.moment += scratch.director(i).transpose() * couple;
    total.largest_couple = std::max(total.largest_couple, couple.norm());
  }
  return total;
}

// The loads are internal. An active stretch or shear gives node forces and element couples
// whose net force and moment vanish exactly on any configuration (the couple (Q t × δn) l̂
// balances the moment of the node forces term by term). An active curvature gives couples
// only; like the kernel's own bending couples, their net moment vanishes to second order in
// the angle between neighbouring elements (here up to 0.15 rad), not exactly.
TEST(ActiveStrain, LoadsAreInternal) {
  const int n = 8;
  RodSpec spec = soft_rod(n);
  spec.rest_curvature = Eigen::Vector3d(2.0, 1.0, 0.5);
  Rod rod(spec);
  ASSERT_TRUE(rod.advance(2000));  // curl into a generic bent and twisted shape

  Vectors stretch(3, n), curvature(3, n - 1);
  for (int i = 0; i < n; ++i) stretch.col(i) = Eigen::Vector3d(0.01 * i, -0.02, 0.05 + 0.01 * i);
  for (int j = 0; j < n - 1; ++j) curvature.col(j) = Eigen::Vector3d(0.3 * j, -1.0, 0.7);

  const Resultant stretching = active_strain_resultant(rod, stretch, Vectors::Zero(3, n - 1));
  ASSERT_GT(stretching.largest_couple, 1e-3);
  EXPECT_LT(stretching.force.norm(), 1e-12);
  EXPECT_LT(stretching.moment.norm(), 1e-12);

  const Resultant bending = active_strain_resultant(rod, Vectors::Zero(3, n), curvature);
  EXPECT_EQ(bending.force.norm(), 0.0);
  EXPECT_LT(bending.moment.norm(), 0.02 * bending.largest_couple);
}

}  // namespace
}  // namespace tendril::physics
