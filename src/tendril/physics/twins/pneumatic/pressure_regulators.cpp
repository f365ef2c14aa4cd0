#include "tendril/physics/twins/pneumatic/pressure_regulators.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics::pneumatic {

namespace {

void require_positive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error(std::string(field) + " must be finite and positive, got " + std::to_string(value),
                "RegulatorSpec");
  }
}

}  // namespace

void RegulatorSpec::validate() const {
  require_positive(max_bar, "max_bar");
  require_positive(ceiling_bar, "ceiling_bar");
  if (ceiling_bar > max_bar) {
    throw Error("ceiling_bar (" + std::to_string(ceiling_bar) + ") exceeds the regulator range (" +
                    std::to_string(max_bar) + " bar)",
                "RegulatorSpec");
  }
  require_positive(inflate_time, "inflate_time");
  require_positive(deflate_time, "deflate_time");
  if (!(disabled_fraction >= 0.0 && disabled_fraction < 1.0)) {
    throw Error("disabled_fraction must lie in [0, 1), got " + std::to_string(disabled_fraction),
                "RegulatorSpec");
  }
}

PressureRegulators::PressureRegulators(const RegulatorSpec& spec) : spec_(spec) {
  spec_.validate();
}

double PressureRegulators::target_for(double command_bar, bool disabled) const {
  const double regulated = std::clamp(command_bar, 0.0, spec_.max_bar);
  const double safe = std::min(regulated, spec_.ceiling_bar);
  return disabled ? spec_.disabled_fraction * safe : safe;
}

void PressureRegulators::set_commands(const ChamberVector& commands_bar) {
  if (!commands_bar.allFinite()) {
    throw Error("pressure commands must be finite", "PressureRegulators::set_commands");
  }
  commands_ = commands_bar;
  for (int k = 0; k < kChambers; ++k) targets_[k] = target_for(commands_[k], spec_.disabled[k]);
}

void PressureRegulators::advance(double dt) {
  if (dt != cached_dt_) {
    cached_dt_ = dt;
    inflate_keep_ = std::exp(-dt / spec_.inflate_time);
    deflate_keep_ = std::exp(-dt / spec_.deflate_time);
  }
  for (int k = 0; k < kChambers; ++k) {
    const double gap = targets_[k] - pressures_[k];
    const double keep = gap > 0.0 ? inflate_keep_ : deflate_keep_;
    pressures_[k] = targets_[k] - gap * keep;
  }
}

void PressureRegulators::reset() {
  commands_.setZero();
  targets_.setZero();
  pressures_.setZero();
}

void PressureRegulators::save_state(SnapshotWriter& out) const {
  out.section("PressureRegulators");
  out.put_matrix(commands_);
  out.put_matrix(targets_);
  out.put_matrix(pressures_);
}

void PressureRegulators::load_state(SnapshotReader& in) {
  in.section("PressureRegulators");
  ChamberVector commands, targets, pressures;
  in.get_matrix(commands);
  in.get_matrix(targets);
  in.get_matrix(pressures);
  commands_ = commands;
  targets_ = targets;
  pressures_ = pressures;
}

}  // namespace tendril::physics::pneumatic
