#include "tendril/physics/forcing/spline_actuation.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/physics/forcing/cubic_spline.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

// p(s) = s (s − 1)(s − 0.3): a cubic vanishing at both ends of a unit arm. A not-a-knot spline
// through four or more of its points is the cubic itself.
double pinned_cubic(double s) { return s * (s - 1.0) * (s - 0.3); }

TEST(CubicSpline, NotAKnotReproducesACubic) {
  Eigen::VectorXd knots(5), points(7);
  knots << 0.0, 0.2, 0.45, 0.7, 1.0;
  points << 0.0, 0.1, 0.33, 0.5, 0.81, 0.95, 1.0;
  const CubicSplineMap spline(knots, points);
  const Eigen::VectorXd values = knots.unaryExpr(&pinned_cubic);
  const Eigen::VectorXd result = spline.evaluate(values);
  for (Eigen::Index p = 0; p < points.size(); ++p) {
    EXPECT_NEAR(result[p], pinned_cubic(points[p]), 1e-14) << "s = " << points[p];
  }
}

TEST(CubicSpline, InterpolatesKnotsAndHandlesThreeKnots) {
  Eigen::VectorXd knots(3), values(3);
  knots << 0.0, 0.5, 1.0;
  values << 0.0, 1.0, 0.0;
  const CubicSplineMap spline(knots, knots);
  EXPECT_LT((spline.evaluate(values) - values).norm(), 1e-14);
  // Three knots: the parabola 4 s (1 − s).
  const CubicSplineMap at_quarter(knots, Eigen::VectorXd::Constant(1, 0.25));
  EXPECT_NEAR(at_quarter.evaluate(values)[0], 0.75, 1e-14);
  EXPECT_THROW(CubicSplineMap(Eigen::Vector2d(0, 1), knots), Error);
  EXPECT_THROW(CubicSplineMap(Eigen::Vector3d(0, 0.5, 0.5), knots), Error);
}

// Hand-computed: with control points at s = 1/3 and 2/3 on a unit arm (knots 0, 1/3, 2/3, 1,
// ends pinned at 0), the not-a-knot spline through four knots is the single cubic through them.
// Values (1, 0): p(s) = c s (s − 2/3)(s − 1) with p(1/3) = 2c/27 = 1, so c = 13.5.
TEST(SplineActuation, CouplesFollowTheSplineAtDistalArcLengths) {
  RodSpec spec;
  spec.n_elements = 6;
  Rod rod(spec);
  SplineActuationSpec actuation;
  actuation.control_points = 2;
  actuation.directions = {true, false, true};
  actuation.max_torque = 75.0;
  auto& muscles = rod.add<SplineActuation>(actuation);
  muscles.set_targets(Eigen::Vector4d(1.0, 0.0, 0.0, -0.5));
  for (int i = 0; i < 6; ++i) {
    const double s = (i + 1) / 6.0;
    const double normal = 13.5 * s * (s - 2.0 / 3.0) * (s - 1.0);
    // Twist, values (0, −0.5): q(s) = c s (s − 1/3)(s − 1) with q(2/3) = −2c/27 = −0.5.
    const double twist = 6.75 * s * (s - 1.0 / 3.0) * (s - 1.0);
    EXPECT_NEAR(muscles.couples()(0, i), 75.0 * normal, 1e-12) << "element " << i;
    EXPECT_NEAR(muscles.couples()(1, i), 0.0, 0.0);
    EXPECT_NEAR(muscles.couples()(2, i), 75.0 * twist, 1e-12) << "element " << i;
  }
  EXPECT_THROW(muscles.set_targets(Eigen::Vector3d(0, 0, 0)), Error);
  // Targets are clipped to [−1, 1].
  muscles.set_targets(Eigen::Vector4d(3.0, 0.0, 0.0, 0.0));
  EXPECT_EQ(muscles.current()[0], 1.0);
}

TEST(SplineActuation, RateLimitMovesControlPointsAtMostPerStep) {
  RodSpec spec;
  spec.n_elements = 10;
  Rod rod(spec);
  SplineActuationSpec actuation;
  actuation.control_points = 2;
  actuation.directions = {true, false, false};
  actuation.max_change_per_step = 0.01;
  auto& muscles = rod.add<SplineActuation>(actuation);
  muscles.set_targets(Eigen::Vector2d(1.0, -0.005));
  ASSERT_TRUE(rod.advance(3));
  EXPECT_NEAR(muscles.current()[0], 0.03, 1e-15);
  EXPECT_NEAR(muscles.current()[1], -0.005, 1e-15);
  ASSERT_TRUE(rod.advance(200));
  EXPECT_EQ(muscles.current()[0], 1.0);
}

// Paired couples: +A(s_i) on element i and −A(s_i) on element i − 1, so they sum to zero.
TEST(SplineActuation, PairedCouplesAreEqualAndOppositeAcrossJoints) {
  RodSpec spec;
  spec.n_elements = 6;
  Rod rod(spec);
  SplineActuationSpec actuation;
  actuation.control_points = 2;
  actuation.directions = {true, false, false};
  actuation.paired = true;
  auto& muscles = rod.add<SplineActuation>(actuation);
  muscles.set_targets(Eigen::Vector2d(1.0, 0.0));
  auto profile = [](int i) {
    const double s = (i + 1) / 6.0;
    return 75.0 * 13.5 * s * (s - 2.0 / 3.0) * (s - 1.0);
  };
  EXPECT_NEAR(muscles.couples()(0, 0), -profile(1), 1e-12);
  for (int i = 1; i < 5; ++i) {
    EXPECT_NEAR(muscles.couples()(0, i), profile(i) - profile(i + 1), 1e-12) << "element " << i;
  }
  EXPECT_NEAR(muscles.couples()(0, 5), profile(5), 1e-12);  // A(L) = 0: pinned end
  EXPECT_NEAR(muscles.couples().row(0).sum(), 0.0, 1e-12);
}

TEST(SplineActuation, SeedControlPointPositions) {
  SplineActuationSpec actuation;
  actuation.control_points = 2;
  actuation.positions = {0.4, 0.9};
  EXPECT_NO_THROW(SplineActuation{actuation});
  actuation.positions = {0.9, 0.4};
  EXPECT_THROW(SplineActuation{actuation}, Error);
  actuation.positions = {0.4};
  EXPECT_THROW(SplineActuation{actuation}, Error);
}

// The control points where the Elastica paper's case 3 puts them, at 0.4 L and 0.9 L: knots
// (0, 0.4, 0.9, 1) with the ends pinned at 0, four knots, so again the single cubic through them.
// Values (1, 0): p(s) = c s (s − 0.9)(s − 1) with p(0.4) = 0.12 c = 1, c = 25/3.
// Values (0, −0.5): q(s) = c s (s − 0.4)(s − 1) with q(0.9) = −0.045 c = −0.5, c = 100/9.
// Uniform knots at 1/3 and 2/3 would give other couples (51.6 instead of 45 at s = 0.1).
TEST(SplineActuation, CustomControlPointPositionsShapeTheCouples) {
  RodSpec spec;
  spec.n_elements = 10;
  Rod rod(spec);
  SplineActuationSpec actuation;
  actuation.control_points = 2;
  actuation.positions = {0.4, 0.9};
  actuation.directions = {true, false, true};
  actuation.max_torque = 75.0;
  auto& muscles = rod.add<SplineActuation>(actuation);
  muscles.set_targets(Eigen::Vector4d(1.0, 0.0, 0.0, -0.5));
  for (int i = 0; i < 10; ++i) {
    const double s = (i + 1) / 10.0;  // distal end of element i, as a fraction of the length
    const double normal = 25.0 / 3.0 * s * (s - 0.9) * (s - 1.0);
    const double twist = 100.0 / 9.0 * s * (s - 0.4) * (s - 1.0);
    EXPECT_NEAR(muscles.couples()(0, i), 75.0 * normal, 1e-12) << "element " << i;
    EXPECT_NEAR(muscles.couples()(2, i), 75.0 * twist, 1e-12) << "element " << i;
  }
  EXPECT_NEAR(muscles.couples()(0, 0), 45.0, 1e-12);
  EXPECT_NEAR(muscles.couples()(0, 3), 75.0, 1e-12);  // at the control point: its value · 75
}

}  // namespace
}  // namespace tendril::physics
