#pragma once

#include <Eigen/Core>

namespace tendril::control {

// The thesis' state estimate of the limb from raw readings (seed 001, §4.2.3), one reading at a
// time — the same code prepares the data sets models are fitted on (data::prepare_limb_data)
// and runs beside a deployed controller (TrackingPolicy), so that a policy sees the limb as its
// training data did:
//   ω_k = (θ_k − θ_{k−1}) / (T_k − T_{k−1})                    eq. 4.5, real time stamps
//   x̄_k = α x_k + (1 − α) x̄_{k−1},  x = (θx, θy, ωx, ωy)      eq. 4.7 as a recursive EMA
// The first reading has ω = 0 and x̄ = x. The thesis writes eq. 4.7 as a blend of the two latest
// raw samples; its author's training code filters recursively (pandas ewm(alpha=0.8,
// adjust=False) on θ and θ̇, spec §2.3) — the form used here, in training and deployment alike.
// α = 1 passes the angles through and estimates the rates by the plain finite difference.
class StateFilter {
 public:
  explicit StateFilter(double alpha = 0.8);

  void reset() { started_ = false; }
  // Takes a reading (time in s, angles in deg) and returns the filtered state
  // (θx, θy [deg], ωx, ωy [deg/s]). Time stamps must increase.
  Eigen::Vector4d update(double time_s, const Eigen::Vector2d& angles_deg);
  // What update would return for this reading, without taking it.
  Eigen::Vector4d next(double time_s, const Eigen::Vector2d& angles_deg) const;
  const Eigen::Vector4d& state() const { return filtered_; }

 private:
  double alpha_;
  bool started_ = false;
  double previous_time_ = 0.0;
  Eigen::Vector2d previous_angles_ = Eigen::Vector2d::Zero();
  Eigen::Vector4d filtered_ = Eigen::Vector4d::Zero();
};

}  // namespace tendril::control
