// Tendon actuation against the closed form of a tendon-driven continuum robot: a constant
// tension T at offset r bends a clamped rod to a constant curvature.
#include "tendril/physics/forcing/tendons.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rod_test_support.hpp"
#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

using testing::add_uniform_damping;
using testing::settle;

// A soft silicone rod, 10 cm long, 5 mm radius, hanging along −z in zero gravity.
RodSpec silicone_rod(int n_elements) {
  RodSpec spec;
  spec.n_elements = n_elements;
  spec.length = 0.1;
  spec.radius = 0.005;
  spec.density = 1200.0;
  spec.youngs_modulus = 1.79e6;
  spec.shear_modulus = spec.youngs_modulus / 3.0;
  spec.direction = -Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitX();
  spec.time_step = 2.0e-5;
  return spec;
}

double bend_stiffness(const RodSpec& spec) {
  return spec.youngs_modulus * std::numbers::pi * std::pow(spec.radius, 4) / 4.0;
}

double axial_stiffness(const RodSpec& spec) {
  return spec.youngs_modulus * std::numbers::pi * spec.radius * spec.radius;
}

// Closed form (Rucker & Webster 2011, straight routing): the moment T r at every cross-section
// and the compression T. The discrete rod's bending couple is B κ / ε³ with κ per rest length
// and ε = E A / (E A + T) the dilatation (the lab force n / e balances T, as in
// RodStatics.AxialStretchUnderEndForce), so κ = T r ε³ / (E I) — with T/EA = 2.8 % here, ε³
// differs from 1 by 8 %, so the test would see it if it were left out. Tolerance 0.1 %, on a
// coarse mesh as on a fine one: the moment T r is applied exactly at every joint.
class TendonsOnMesh : public ::testing::TestWithParam<int> {};

TEST_P(TendonsOnMesh, ConstantTensionBendsToTheClosedFormConstantCurvature) {
  const int n = GetParam();
  const RodSpec spec = silicone_rod(n);
  const double r = 0.0035;
  const double target_angle = std::numbers::pi / 2.0;  // 90° over the rod
  const double tension = target_angle / spec.length * bend_stiffness(spec) / r;
  Rod rod(spec);
  rod.add<FixedEnd>();
  auto& tendons = rod.add<Tendons>(std::vector<Eigen::Vector3d>{Eigen::Vector3d(r, 0.0, 0.0)});
  tendons.set_tension(0, tension);
  add_uniform_damping(rod, 200.0);
  ASSERT_TRUE(settle(rod, 5.0, 1e-6));

  const double dilatation = axial_stiffness(spec) / (axial_stiffness(spec) + tension);
  ASSERT_LT(dilatation, 0.98);
  const double expected = tension * r * std::pow(dilatation, 3) / bend_stiffness(spec);
  const Vectors& kappa = rod.curvatures();
  for (int j = 0; j < kappa.cols(); ++j) {
    // Material frame: a tendon on the +d1 side bends the rod about d2, towards +d1.
    EXPECT_NEAR(kappa(1, j), expected, 1e-3 * expected) << "Voronoi point " << j;
    EXPECT_NEAR(kappa(0, j), 0.0, 1e-6 * expected);
    EXPECT_NEAR(kappa(2, j), 0.0, 1e-6 * expected);
  }
  // The tip turned towards +x (the tendon's side) by κ (L − l̂): n − 1 joints of D̂ each.
  const Eigen::Vector3d tangent = rod.tip_directors().row(2);
  const double tip_angle = std::atan2(tangent.x(), -tangent.z());
  EXPECT_NEAR(tip_angle, expected * spec.length * (n - 1.0) / n, 1e-3 * tip_angle);
  EXPECT_NEAR(tendons.tension(0), tension, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Elements, TendonsOnMesh, ::testing::Values(8, 40));

// An offset at 30° around the rod bends the rod in that plane, by the same amount.
TEST(Tendons, TheBendingPlaneFollowsTheOffset) {
  const RodSpec spec = silicone_rod(20);
  const double r = 0.003, phi = std::numbers::pi / 6.0;
  Rod rod(spec);
  rod.add<FixedEnd>();
  auto& tendons = rod.add<Tendons>(
      std::vector<Eigen::Vector3d>{Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), 0.0)});
  tendons.set_tension(0, 1.0);
  add_uniform_damping(rod, 200.0);
  ASSERT_TRUE(settle(rod, 5.0, 1e-6));
  // d1 = x, d2 = d3 × d1 = −y at the base; the tip moves along Q_0ᵀ (cos φ, sin φ, 0).
  const Eigen::Vector3d direction(std::cos(phi), -std::sin(phi), 0.0);
  const Eigen::Vector3d tip = rod.tip_position();
  const Eigen::Vector3d sideways(tip.x(), tip.y(), 0.0);
  ASSERT_GT(sideways.norm(), 0.01);
  EXPECT_NEAR(sideways.normalized().dot(direction), 1.0, 1e-9);
}

// The path of a tendon on the inside of a constant-curvature bend of angle θ is shorter by r θ
// (its arc has radius 1/κ − r); a spring-like tendon law T = T₀ + K (l − l̂) settles where the
// curvature and the shortened path agree.
TEST(Tendons, AnElasticTendonLosesTensionAsItShortens) {
  const RodSpec spec = silicone_rod(40);
  const double r = 0.0035, stiffness = 300.0, preload = 4.0;
  Rod rod(spec);
  rod.add<FixedEnd>();
  auto& tendons = rod.add<Tendons>(std::vector<Eigen::Vector3d>{Eigen::Vector3d(r, 0.0, 0.0)});
  const double rest = tendons.rest_path_length(0);
  EXPECT_NEAR(rest, spec.length, 1e-12) << "a straight tendon is as long as the rod";
  tendons.set_tension_law(0, preload, stiffness);
  add_uniform_damping(rod, 200.0);
  ASSERT_TRUE(settle(rod, 5.0, 1e-6));
  ASSERT_TRUE(rod.advance(1));

  const double tension = tendons.tension(0);
  const double shortening = rest - tendons.path_length(0);
  EXPECT_NEAR(tension, preload - stiffness * shortening, 1e-9);
  EXPECT_LT(tension, 0.8 * preload);
  // l = Σ over joints of the arc on the inside: the rod's compressed length minus r θ.
  const double dilatation = axial_stiffness(spec) / (axial_stiffness(spec) + tension);
  const double kappa = tension * r * std::pow(dilatation, 3) / bend_stiffness(spec);
  const double angle = kappa * spec.length * 39.0 / 40.0;
  EXPECT_NEAR(shortening, spec.length * (1.0 - dilatation) + r * angle, 0.01 * shortening);
}

TEST(Tendons, SlackTendonsDoNotPush) {
  const RodSpec spec = silicone_rod(10);
  Rod rod(spec);
  rod.add<FixedEnd>();
  auto& tendons = rod.add<Tendons>(std::vector<Eigen::Vector3d>{Eigen::Vector3d(0.003, 0, 0)});
  tendons.set_tension(0, -5.0);
  ASSERT_TRUE(rod.advance(2000));
  EXPECT_EQ(tendons.tension(0), 0.0);
  EXPECT_LT((rod.tip_position() - Eigen::Vector3d(0, 0, -spec.length)).norm(), 1e-15);
}

TEST(Tendons, BadOffsetsAndLawsAreRejected) {
  using tendril::testing::error_message;
  EXPECT_NE(error_message([] { Tendons({}); }), "no error");
  EXPECT_NE(error_message([] { Tendons({Eigen::Vector3d(0.0, 0.0, 0.0)}); }), "no error");
  EXPECT_NE(error_message([] { Tendons({Eigen::Vector3d(0.001, 0.0, 0.001)}); }), "no error");
  Tendons tendons({Eigen::Vector3d(0.001, 0.0, 0.0)});
  EXPECT_NE(error_message([&] { tendons.set_tension(1, 1.0); }).find("no tendon 1"),
            std::string::npos);
  EXPECT_NE(error_message([&] { tendons.set_tension_law(0, 1.0, -1.0); }), "no error");
  EXPECT_NE(error_message([&] { tendons.set_tension(0, NAN); }), "no error");
}

}  // namespace
}  // namespace tendril::physics
