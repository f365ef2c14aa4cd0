#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace tendril::physics {

struct ClosestPoints {
  Eigen::Vector3d on_first;
  Eigen::Vector3d on_second;
};

// The closest points between segments [p0, p1] and [q0, q1] (minimizing |p(s) − q(t)| over
// s, t ∈ [0, 1]); degenerate segments are handled as points.
inline ClosestPoints closest_points_between_segments(const Eigen::Vector3d& p0,
                                                     const Eigen::Vector3d& p1,
                                                     const Eigen::Vector3d& q0,
                                                     const Eigen::Vector3d& q1) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double kTiny = 1e-300;
  double s = 0.0, t = 0.0;
  if (a <= kTiny && e <= kTiny) return {p0, q0};
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2);
      const double denominator = a * e - b * b;  // ≥ 0; zero for parallel segments
      s = denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      // If t left [0, 1], clamp it and recompute the best s for that end of the second segment.
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {p0 + s * d1, q0 + t * d2};
}

}  // namespace tendril::physics
