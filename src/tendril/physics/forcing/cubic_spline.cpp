#include "tendril/physics/forcing/cubic_spline.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

// Second derivatives M at the knots of the not-a-knot spline through (x, y).
Eigen::VectorXd second_derivatives(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  const Eigen::Index m = x.size();
  const Eigen::VectorXd h = x.tail(m - 1) - x.head(m - 1);
  if (m == 3) {
    // The parabola through three points: constant second derivative.
    const double curvature = 2.0 * ((y[2] - y[1]) / h[1] - (y[1] - y[0]) / h[0]) / (x[2] - x[0]);
    return Eigen::VectorXd::Constant(3, curvature);
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
  // Not-a-knot: M'''continuous at x_1 and x_{m−2}, i.e. (M1 − M0)/h0 = (M2 − M1)/h1.
  a(0, 0) = h[1];
  a(0, 1) = -(h[0] + h[1]);
  a(0, 2) = h[0];
  a(m - 1, m - 3) = h[m - 2];
  a(m - 1, m - 2) = -(h[m - 3] + h[m - 2]);
  a(m - 1, m - 1) = h[m - 3];
  // Continuity of the first derivative at interior knots.
  for (Eigen::Index i = 1; i + 1 < m; ++i) {
    a(i, i - 1) = h[i - 1];
    a(i, i) = 2.0 * (h[i - 1] + h[i]);
    a(i, i + 1) = h[i];
    b[i] = 6.0 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1]);
  }
  return a.fullPivLu().solve(b);
}

double evaluate_piece(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& m2,
                double point) {
  const Eigen::Index last = x.size() - 2;
  Eigen::Index i = 0;
  while (i < last && point > x[i + 1]) ++i;
  const double h = x[i + 1] - x[i];
  const double left = x[i + 1] - point, right = point - x[i];
  return m2[i] * left * left * left / (6.0 * h) + m2[i + 1] * right * right * right / (6.0 * h) +
         (y[i] / h - m2[i] * h / 6.0) * left + (y[i + 1] / h - m2[i + 1] * h / 6.0) * right;
}

}  // namespace

CubicSplineMap::CubicSplineMap(const Eigen::VectorXd& knots, const Eigen::VectorXd& points) {
  require(knots.size() >= 3, "a cubic spline needs at least 3 knots", "CubicSplineMap");
  for (Eigen::Index i = 0; i < knots.size(); ++i) {
    require(std::isfinite(knots[i]) && (i == 0 || knots[i] > knots[i - 1]),
            "knots must be finite and strictly increasing", "CubicSplineMap");
  }
  require(points.allFinite(), "evaluation points must be finite", "CubicSplineMap");
  // The spline is linear in the knot values: column k is the spline through the k-th unit vector.
  weights_.resize(points.size(), knots.size());
  for (Eigen::Index k = 0; k < knots.size(); ++k) {
    const Eigen::VectorXd unit = Eigen::VectorXd::Unit(knots.size(), k);
    const Eigen::VectorXd m2 = second_derivatives(knots, unit);
    for (Eigen::Index p = 0; p < points.size(); ++p) weights_(p, k) = evaluate_piece(knots, unit, m2, points[p]);
  }
}

}  // namespace tendril::physics
