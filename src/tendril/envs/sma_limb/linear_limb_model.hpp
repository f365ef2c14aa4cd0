#pragma once

#include "tendril/envs/learned/dynamics_model.hpp"

namespace tendril::envs::sma_limb {

// A torch-free stand-in for a learned model of the SMA limb: each bend axis a critically damped
// second-order system driven by its throttle, stepped by semi-implicit Euler,
//   θ̇_{t+1} = θ̇_t + Δt (ω² (K u_t − θ_t) − 2ω θ̇_t),   θ_{t+1} = θ_t + Δt θ̇_{t+1},
// with the thesis' control period Δt = 0.075 s, ω = 2 rad/s and K = 9° per throttle (so a
// throttle of ±10 settles at ±90°, past the task's ±80° bounds). Not the limb (it has no heat, no
// hysteresis, no coupling): SmaLimb/LearnedReach-v0 uses it when no trained model is named, so
// the environment runs, and is tested, without the dynamics layer. Degrees and degrees/second.
class LinearLimbModel final : public DynamicsModel {
 public:
  static constexpr double kPeriod = 0.075;          // s
  static constexpr double kNaturalFrequency = 2.0;  // ω, rad/s
  static constexpr double kGain = 9.0;              // K, degrees per throttle

  // `window` rows of history (the model reads only the newest; 100 as seed 001's models, so
  // policies can observe that much history).
  explicit LinearLimbModel(int window = 100);

  int state_dim() const override { return 4; }
  int input_dim() const override { return 2; }
  int window_length() const override { return window_; }
  double sample_period() const override { return kPeriod; }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override;

 private:
  int window_;
};

}  // namespace tendril::envs::sma_limb
