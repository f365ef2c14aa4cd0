#pragma once

#include <array>
#include <cstdint>

#include "tendril/physics/forcing/tendons.hpp"
#include "tendril/physics/rod/rod_part.hpp"
#include "tendril/physics/twins/sma/sma_coil.hpp"

namespace tendril::physics {

// The four SMA coils of the thesis' limb (seed 001, Ch. 3, Fig. 3.1): embedded at the cardinal
// directions of the cross-section, at `tendon_offset` from the centreline, each driven by its own
// MOSFET with an 8-bit PWM duty from an 11.1 V supply. Coil order (the firmware's channels):
//   0: +x (material +d1), 1: −x, 2: +y (material +d2), 3: −y.
// A coil on +x contracts to bend the limb towards +x. Antagonistic pairs (+x/−x, +y/−y) must
// never be on together (seed 001, §4.1.2: that would compress the limb).
struct SmaActuatorSpec {
  SmaCoilSpec coil;
  double tendon_offset = 0.0035;  // m from the centreline
  // The coils' heat balance and phase advance in steps of this length (s) between PWM changes;
  // a PWM change first brings them exactly up to the moment of the change.
  double thermal_step = 0.002;
  // Degradation of each coil when the limb is built (worn coils stay worn).
  std::array<double, 4> initial_degradation{0.0, 0.0, 0.0, 0.0};

  void validate() const;
};

class SmaActuator final : public RodPart {
 public:
  static constexpr int kCoils = 4;
  static constexpr int kMaxPwm = 255;

  explicit SmaActuator(const SmaActuatorSpec& spec);

  uint32_t stages() const override { return kStartStep | kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void start_step(const RodModel& model, RodState& state, double step) override;
  void add_loads(const RodModel& model, RodState& state) override;
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override {
    tendons_.add_load_derivatives(model, state, jacobian);
  }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  // Sets the four PWM values (0–255) from `time` (s, the rod's time now) on. Raises Error for a
  // value outside 0–255 or both coils of an antagonistic pair on.
  void set_pwm(const std::array<int, 4>& pwm, double time);
  const std::array<int, 4>& pwm() const { return pwm_; }

  const SmaActuatorSpec& spec() const { return spec_; }
  const SmaCoilState& coil(int index) const { return coils_[index]; }
  // Of the last step, N; and the coil's path (lab frame) for drawing.
  double tension(int index) const { return tendons_.tension(index); }
  Eigen::Matrix3Xd coil_path(const RodState& state, int index) const {
    return tendons_.path(state, index);
  }

 private:
  void advance_coils(double h);
  void update_tension_laws();

  SmaActuatorSpec spec_;
  CoilThermal thermal_;
  Tendons tendons_;
  std::array<SmaCoilState, 4> coils_;
  std::array<int, 4> pwm_{0, 0, 0, 0};
  double thermal_time_ = 0.0;  // the time the coils' state is at, s
};

}  // namespace tendril::physics
