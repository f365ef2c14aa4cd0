#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace tendril::physics {

// Rotations of director frames. Conventions (Gazzola et al. 2018): a director matrix Q has rows
// d1, d2, d3 and maps lab-frame vectors to the material frame. A material-frame angular velocity
// ω evolves the frame as dQ/dt = −[ω]× Q, so one step of length h is Q ← exp(−h[ω]×) Q; the
// curvature κ between neighbouring frames follows the same rule along the arc length.

// The rotation exp(−[θ]×) for a rotation vector θ (radians), by Rodrigues' formula. Small angles
// use the Taylor series of sin φ / φ and (1 − cos φ) / φ², which are exact to double precision
// for φ < 0.1 and avoid sin/cos in the common case of a small time step.
inline Eigen::Matrix3d exp_rotation_minus(const Eigen::Vector3d& theta) {
  const double phi2 = theta.squaredNorm();
  double sin_over_phi, one_minus_cos_over_phi2;
  if (phi2 < 1e-2) {
    sin_over_phi = 1.0 - phi2 / 6.0 * (1.0 - phi2 / 20.0 * (1.0 - phi2 / 42.0 * (1.0 - phi2 / 72.0)));
    one_minus_cos_over_phi2 =
        0.5 * (1.0 - phi2 / 12.0 * (1.0 - phi2 / 30.0 * (1.0 - phi2 / 56.0 * (1.0 - phi2 / 90.0))));
  } else {
    const double phi = std::sqrt(phi2);
    sin_over_phi = std::sin(phi) / phi;
    one_minus_cos_over_phi2 = (1.0 - std::cos(phi)) / phi2;
  }
  // exp(−[θ]×) = I − (sin φ/φ)[θ]× + ((1 − cos φ)/φ²)[θ]×², with [θ]×² = θθᵀ − φ² I.
  const double a = sin_over_phi, b = one_minus_cos_over_phi2;
  const double x = theta.x(), y = theta.y(), z = theta.z();
  Eigen::Matrix3d r;
  r(0, 0) = 1.0 + b * (x * x - phi2);
  r(1, 1) = 1.0 + b * (y * y - phi2);
  r(2, 2) = 1.0 + b * (z * z - phi2);
  r(0, 1) = a * z + b * x * y;
  r(1, 0) = -a * z + b * x * y;
  r(0, 2) = -a * y + b * x * z;
  r(2, 0) = a * y + b * x * z;
  r(1, 2) = a * x + b * y * z;
  r(2, 1) = -a * x + b * y * z;
  return r;
}

// θ / sin θ as a function of x = sin² θ, for θ below 90°: the series of asin(s)/s to s²², exact
// to double precision for x < kSmallAngleSine2 (θ < 11.5°). Branch-free, so loops over elements
// vectorize; larger angles take atan2.
constexpr double kSmallAngleSine2 = 4e-2;
inline double theta_over_sin_theta_series(double x) {
  return 1.0 + x * (1.0 / 6 + x * (3.0 / 40 + x * (5.0 / 112 + x * (35.0 / 1152 +
         x * (63.0 / 2816 + x * (231.0 / 13312 + x * (143.0 / 10240 + x * (6435.0 / 557056 +
         x * (12155.0 / 1245184 + x * (46189.0 / 5505024 + x * (88179.0 / 12058624)))))))))));
}

// θ / sin θ from sin² θ and cos θ, for any angle in [0, π).
inline double theta_over_sin_theta(double sin2, double cos_theta) {
  if (cos_theta > 0.0 && sin2 < kSmallAngleSine2) return theta_over_sin_theta_series(sin2);
  const double sin_theta = std::sqrt(sin2);
  // θ = π has no defined axis in this form; frames that far apart are a blown-up state.
  return sin_theta > 0.0 ? std::atan2(sin_theta, cos_theta) / sin_theta : 0.0;
}

// The rotation vector a with exp([a]×) = R for a proper rotation R (angle below π).
inline Eigen::Vector3d log_rotation(const Eigen::Matrix3d& r) {
  // ½(R − Rᵀ)^∨ = sin θ · axis and (tr R − 1)/2 = cos θ.
  const Eigen::Vector3d s(0.5 * (r(2, 1) - r(1, 2)), 0.5 * (r(0, 2) - r(2, 0)),
                          0.5 * (r(1, 0) - r(0, 1)));
  return theta_over_sin_theta(s.squaredNorm(), 0.5 * (r.trace() - 1.0)) * s;
}

// The 3×3 matrix [a]× with [a]× b = a × b.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

}  // namespace tendril::physics
