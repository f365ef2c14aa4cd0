#pragma once

#include "tendril/envs/learned/dynamics_model.hpp"
#include "tendril/envs/pneumatic/arm_dynamics.hpp"

namespace tendril::envs::pneumatic {

// A torch-free stand-in for a learned model of the pneumatic arm (seed 002 eq. (1)): the tips
// approach, at first order, a steady state linear in the chamber pressures,
//   x_{t+1} = x_t + β (x_rest + G τ_t − x_t),   β = 1 − e^{−Δt/τ_lag},
// with Δt = 0.1 s, τ_lag = 0.3 s. G moves module m's tip and every tip below it: a chamber at
// angle φ (0°, 120°, 240°) shifts them by kBend per bar along −(cos φ, sin φ) (a chamber bends its
// module away from itself) and by kExtension per bar down (three equal pressures cancel in x, y
// and only extend, 10 %/bar of a 199.3 mm module). Not the arm (no rod, no drift, no hysteresis):
// PneumaticArm/LearnedReach-v0 uses it when no trained model is named, so the environment runs,
// and is tested, without the dynamics layer. States in mm (robot frame), inputs in bar.
class LinearArmModel final : public DynamicsModel {
 public:
  static constexpr double kPeriod = 0.1;                   // s
  static constexpr double kLag = 0.3;                      // s
  static constexpr double kBend = 40.0;                    // mm per bar, per module spanned
  static constexpr double kExtension = 199.3 * 0.1 / 3.0;  // mm per bar and chamber

  // `window` rows of history (the model reads only the newest; 3 as the seed's model).
  explicit LinearArmModel(int window = 3);

  // The tips with every chamber vented: the modules hanging straight, 199.3 mm each.
  static TipVector rest();
  // x_rest + G τ for constant pressures τ (bar).
  static TipVector steady_state(const ChamberVector& pressures_bar);

  int state_dim() const override { return 9; }
  int input_dim() const override { return 9; }
  int window_length() const override { return window_; }
  double sample_period() const override { return kPeriod; }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override;

 private:
  int window_;
};

}  // namespace tendril::envs::pneumatic
