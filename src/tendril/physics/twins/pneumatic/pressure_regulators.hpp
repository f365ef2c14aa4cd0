#pragma once

#include <array>

#include "tendril/core/snapshot.hpp"
#include "tendril/physics/twins/pneumatic/chambers.hpp"

namespace tendril::physics::pneumatic {

// The nine electronic proportional regulators (seed 002 §III-A: series K8P, 0–4 bar) and the
// chambers they fill, in gauge bar.
//
// A command is clamped to the regulator's range [0, max_bar] and then to the safety ceiling
// (1.5 bar in the seed) — for any command, so no chamber is ever driven above the ceiling. The
// chamber pressure follows its target as a first-order lag with one time constant for filling
// and a longer one for venting (seed 002 §III-B: "actuating the pneumatic chambers at high
// frequency leaves less time for them to inflate and deflate fully"); integrated exactly over
// each step, dp = (target − p)(1 − exp(−dt/τ)). A disabled chamber (the damage scenarios, §V-A:
// its supply "disrupted" by a manual knob) reaches only `disabled_fraction` of its command:
// 0 by default, i.e. vented whatever the command.
struct RegulatorSpec {
  double max_bar = 4.0;                    // regulator range, bar
  double ceiling_bar = 1.5;                // safety ceiling, bar, ≤ max_bar
  double inflate_time = 0.15;              // s, τ while the pressure rises
  double deflate_time = 0.40;              // s, τ while it falls
  double disabled_fraction = 0.0;          // of the command a disabled chamber reaches, [0, 1)
  std::array<bool, kChambers> disabled{};  // flat chamber index

  // Raises tendril::Error naming the first invalid field.
  void validate() const;
};

class PressureRegulators {
 public:
  explicit PressureRegulators(const RegulatorSpec& spec);

  // Commands in bar, any finite values (non-finite ones raise Error): they are clamped here.
  void set_commands(const ChamberVector& commands_bar);
  // Advances the chamber pressures by `dt` seconds toward their targets.
  void advance(double dt);
  // Vents every chamber at once and clears the commands (a new trial).
  void reset();

  const ChamberVector& commands() const { return commands_; }    // as given, bar
  const ChamberVector& targets() const { return targets_; }      // after range, ceiling, damage
  const ChamberVector& pressures() const { return pressures_; }  // in the chambers, bar
  const RegulatorSpec& spec() const { return spec_; }

  // The target a regulator sets for `command` on a chamber that is (not) disabled.
  double target_for(double command_bar, bool disabled) const;

  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  RegulatorSpec spec_;
  ChamberVector commands_ = ChamberVector::Zero();
  ChamberVector targets_ = ChamberVector::Zero();
  ChamberVector pressures_ = ChamberVector::Zero();
  // exp(−dt/τ) of the last dt, cached.
  double cached_dt_ = -1.0, inflate_keep_ = 0.0, deflate_keep_ = 0.0;
};

}  // namespace tendril::physics::pneumatic
