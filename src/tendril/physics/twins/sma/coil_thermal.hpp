#pragma once

#include <Eigen/Core>

namespace tendril::physics {

// Heat balance of one SMA coil embedded in a silicone limb: a fast node (the wire) heated by
// Joule heating and a slow node (the silicone around it), each with Newton cooling.
//   C_w dT_w/dt = P − g_wa (T_w − T_a) − g_wb (T_w − T_b)
//   C_b dT_b/dt = g_wb (T_w − T_b) − g_ba (T_b − T_a)
// P = D V² / R for a PWM duty D ∈ [0, 1] of the supply V (PWM at the Arduino's ≈ 490 Hz is far
// faster than the wire's thermal time constant, so it acts as its mean power). Temperatures in
// °C, capacities in J/K, conductances in W/K. The thesis (seed 001) reports that its coils return
// close to ambient ≈ 30 s after heating (§5.1.1, Fig. A.4, k = 0.2 s⁻¹) and that a 30 s cool-down
// leaves visible hysteresis where a 180 s one does not (Fig. 1.1c): the wire's time constant is
// a few seconds, the silicone's about a minute.
//
// The defaults (ours; the thesis gives no coil data) make the wire's time constant ≈ 1.5 s and
// the silicone's ≈ 57 s; most of the wire's heat flows into the silicone, as for a coil embedded
// in it, and the silicone sheds it to the air and the mount. With them the twin's calibrated
// input bounds land near the thesis' and hours of exploration keep the coils in their working
// range (docs/results/sma_limb.md). 11.1 V on 7.1 Ω is ≈ 17 W at full duty, ≈ 2.6 W at the
// stiff limb's 15 %.
struct CoilThermalSpec {
  double ambient_temperature = 22.0;  // T_a, °C
  double supply_voltage = 11.1;       // V, the thesis' supply
  double resistance = 7.1;            // R, Ω
  double wire_capacity = 0.03;        // C_w, J/K
  double wire_to_ambient = 0.002;     // g_wa, W/K
  double wire_to_body = 0.018;        // g_wb, W/K
  double body_capacity = 1.8;         // C_b, J/K
  double body_to_ambient = 0.03;      // g_ba, W/K

  // Raises tendril::Error naming the first invalid field.
  void validate() const;
  double power(double duty) const { return duty * supply_voltage * supply_voltage / resistance; }
};

// The exact solution of the linear two-node network over a step with constant power:
// x(t + h) = e^{A h} x(t) + A⁻¹ (e^{A h} − I) b P, x = (T_w − T_a, T_b − T_a), b = (1/C_w, 0).
class CoilThermal {
 public:
  explicit CoilThermal(const CoilThermalSpec& spec);

  const CoilThermalSpec& spec() const { return spec_; }
  // Advances the wire and body temperatures (°C) by `h` seconds at `power` watts.
  void advance(double& wire, double& body, double power, double h) const;
  // The temperatures (wire, body) that a constant power settles to, °C.
  Eigen::Vector2d steady_state(double power) const;
  // The network's two time constants, fast first, s.
  Eigen::Vector2d time_constants() const;

 private:
  Eigen::Matrix2d propagator(double h) const;  // e^{A h}

  CoilThermalSpec spec_;
  Eigen::Matrix2d system_;           // A
  Eigen::Vector2d eigenvalues_;      // λ_fast < λ_slow < 0
  Eigen::Vector2d input_;            // b, 1/(J/K)
  Eigen::Vector2d steady_per_watt_;  // −A⁻¹ b, K/W
};

}  // namespace tendril::physics
