#include "tendril/control/reference_patterns.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::control {

namespace {

constexpr double kSpacing = 5.0;  // deg

Eigen::Matrix2Xd from_points(std::initializer_list<std::array<double, 2>> points) {
  Eigen::Matrix2Xd result(2, static_cast<Eigen::Index>(points.size()));
  Eigen::Index i = 0;
  for (const auto& point : points) result.col(i++) = Eigen::Vector2d(point[0], point[1]);
  return result;
}

Eigen::Matrix2Xd concatenate(const std::vector<Eigen::Matrix2Xd>& parts) {
  Eigen::Index total = 0;
  for (const auto& part : parts) total += part.cols();
  Eigen::Matrix2Xd result(2, total);
  Eigen::Index at = 0;
  for (const auto& part : parts) {
    result.middleCols(at, part.cols()) = part;
    at += part.cols();
  }
  return result;
}

// One letter 30° wide and 40° tall centred on (centre_x, 0), as corner points.
Eigen::Matrix2Xd letter(char name, double centre_x) {
  const double l = centre_x - 15.0, r = centre_x + 15.0, top = 20.0, bottom = -20.0;
  switch (name) {
    case 'S':
      return from_points({{r, top}, {l, top}, {l, 0.0}, {r, 0.0}, {r, bottom}, {l, bottom}});
    case 'M':
      return from_points({{l, bottom}, {l, top}, {centre_x, 0.0}, {r, top}, {r, bottom}});
    default:  // 'L'
      return from_points({{l, top}, {l, bottom}, {r, bottom}});
  }
}

}  // namespace

Eigen::Matrix2Xd densify(const Eigen::Matrix2Xd& corners, double spacing) {
  require(corners.cols() >= 1 && spacing > 0.0, "densify needs points and a spacing > 0",
          "control::densify");
  std::vector<Eigen::Vector2d> points{corners.col(0)};
  for (Eigen::Index i = 1; i < corners.cols(); ++i) {
    const Eigen::Vector2d from = corners.col(i - 1), to = corners.col(i);
    const int pieces = std::max(1, static_cast<int>(std::ceil((to - from).norm() / spacing)));
    for (int k = 1; k <= pieces; ++k) points.push_back(from + (to - from) * k / pieces);
  }
  Eigen::Matrix2Xd result(2, static_cast<Eigen::Index>(points.size()));
  for (size_t i = 0; i < points.size(); ++i) result.col(static_cast<Eigen::Index>(i)) = points[i];
  return result;
}

Eigen::Matrix2Xd reference_pattern(std::string_view name) {
  if (name == "circle") {
    const int n = static_cast<int>(std::ceil(2.0 * std::numbers::pi * 40.0 / kSpacing));
    Eigen::Matrix2Xd points(2, n + 1);
    for (int k = 0; k <= n; ++k) {
      const double phase = 2.0 * std::numbers::pi * k / n;
      points.col(k) = 40.0 * Eigen::Vector2d(std::cos(phase), std::sin(phase));
    }
    return points;
  }
  if (name == "square") {
    return densify(from_points({{40, -40}, {40, 40}, {-40, 40}, {-40, -40}, {40, -40}}), kSpacing);
  }
  if (name == "spiral") {
    // Candidates < 1° apart along r = 50 s, φ = 4π s; a point is kept when the next candidate
    // would be more than kSpacing from the last kept one.
    std::vector<Eigen::Vector2d> points{Eigen::Vector2d::Zero()};
    Eigen::Vector2d previous = Eigen::Vector2d::Zero();
    for (int k = 1; k <= 400; ++k) {
      const double s = k / 400.0, phase = 4.0 * std::numbers::pi * s;
      const Eigen::Vector2d point = 50.0 * s * Eigen::Vector2d(std::cos(phase), std::sin(phase));
      if ((point - points.back()).norm() > kSpacing) points.push_back(previous);
      previous = point;
    }
    points.push_back(previous);
    Eigen::Matrix2Xd result(2, static_cast<Eigen::Index>(points.size()));
    for (size_t i = 0; i < points.size(); ++i) result.col(static_cast<Eigen::Index>(i)) = points[i];
    return result;
  }
  if (name == "sml") {
    return densify(concatenate({letter('S', -50.0), letter('M', 0.0), letter('L', 50.0)}),
                   kSpacing);
  }
  throw Error("unknown pattern '" + std::string(name) + "' (circle, square, spiral, sml)",
              "control::reference_pattern");
}

std::vector<std::string> reference_pattern_names() { return {"circle", "square", "spiral", "sml"}; }

double distance_to_path(const Eigen::Vector2d& point, const Eigen::Matrix2Xd& path) {
  double best = (point - path.col(0)).norm();
  for (Eigen::Index i = 1; i < path.cols(); ++i) {
    const Eigen::Vector2d from = path.col(i - 1), segment = path.col(i) - from;
    const double length2 = segment.squaredNorm();
    const double t =
        length2 > 0.0 ? std::clamp((point - from).dot(segment) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, (point - from - t * segment).norm());
  }
  return best;
}

double tracking_rmse(const Eigen::Matrix2Xd& trajectory, const Eigen::Matrix2Xd& path) {
  require(trajectory.cols() >= 1 && path.cols() >= 1, "tracking_rmse needs points",
          "control::tracking_rmse");
  double sum = 0.0;
  for (Eigen::Index i = 0; i < trajectory.cols(); ++i) {
    const double d = distance_to_path(trajectory.col(i), path);
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(trajectory.cols()));
}

}  // namespace tendril::control
