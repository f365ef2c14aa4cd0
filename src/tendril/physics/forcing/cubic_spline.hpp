#pragma once

#include <Eigen/Core>

namespace tendril::physics {

// A cubic interpolating spline with not-a-knot end conditions (the third derivative is
// continuous at the second and the second-to-last knot; with three knots, the parabola through
// them), precomputed as a linear map from knot values to values at fixed evaluation points:
// values = weights · knot_values. The knots stay fixed, so evaluation is one small
// matrix-vector product.
class CubicSplineMap {
 public:
  // `knots` strictly increasing, at least 3; `points` where the spline is evaluated (values
  // outside the knot range extrapolate the end polynomials).
  CubicSplineMap(const Eigen::VectorXd& knots, const Eigen::VectorXd& points);

  const Eigen::MatrixXd& weights() const { return weights_; }  // points × knots
  Eigen::VectorXd evaluate(const Eigen::VectorXd& knot_values) const { return weights_ * knot_values; }

 private:
  Eigen::MatrixXd weights_;
};

}  // namespace tendril::physics
