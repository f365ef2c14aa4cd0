#include "tendril/physics/twins/sma/coil_thermal.hpp"

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

void require_positive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error(std::string(field) + " must be finite and positive, got " + std::to_string(value),
                "CoilThermalSpec");
  }
}

}  // namespace

void CoilThermalSpec::validate() const {
  if (!std::isfinite(ambient_temperature)) {
    throw Error("ambient_temperature must be finite", "CoilThermalSpec");
  }
  require_positive(supply_voltage, "supply_voltage");
  require_positive(resistance, "resistance");
  require_positive(wire_capacity, "wire_capacity");
  require_positive(wire_to_ambient, "wire_to_ambient");
  require_positive(wire_to_body, "wire_to_body");
  require_positive(body_capacity, "body_capacity");
  require_positive(body_to_ambient, "body_to_ambient");
}

CoilThermal::CoilThermal(const CoilThermalSpec& spec) : spec_(spec) {
  spec_.validate();
  const double cw = spec_.wire_capacity, cb = spec_.body_capacity;
  system_ << -(spec_.wire_to_ambient + spec_.wire_to_body) / cw, spec_.wire_to_body / cw,
      spec_.wire_to_body / cb, -(spec_.wire_to_body + spec_.body_to_ambient) / cb;
  // A is similar to a symmetric negative-definite matrix: real, distinct, negative eigenvalues.
  const double half_trace = 0.5 * system_.trace();
  const double root = std::sqrt(half_trace * half_trace - system_.determinant());
  eigenvalues_ << half_trace - root, half_trace + root;
  input_ << 1.0 / cw, 0.0;
  steady_per_watt_ = -system_.inverse() * input_;
}

Eigen::Matrix2d CoilThermal::propagator(double h) const {
  // Sylvester's formula for a 2 × 2 matrix with distinct eigenvalues λ1, λ2:
  // e^{A h} = (e^{λ1 h} (A − λ2 I) − e^{λ2 h} (A − λ1 I)) / (λ1 − λ2).
  const double l1 = eigenvalues_[0], l2 = eigenvalues_[1];
  const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
  return (std::exp(l1 * h) * (system_ - l2 * identity) -
          std::exp(l2 * h) * (system_ - l1 * identity)) /
         (l1 - l2);
}

void CoilThermal::advance(double& wire, double& body, double power, double h) const {
  const Eigen::Matrix2d decay = propagator(h);
  const Eigen::Vector2d steady = steady_per_watt_ * power;
  // x(h) = x∞ + e^{A h} (x(0) − x∞) with x∞ = −A⁻¹ b P.
  const Eigen::Vector2d excess(wire - spec_.ambient_temperature, body - spec_.ambient_temperature);
  const Eigen::Vector2d next = steady + decay * (excess - steady);
  wire = spec_.ambient_temperature + next[0];
  body = spec_.ambient_temperature + next[1];
}

Eigen::Vector2d CoilThermal::steady_state(double power) const {
  return Eigen::Vector2d::Constant(spec_.ambient_temperature) + steady_per_watt_ * power;
}

Eigen::Vector2d CoilThermal::time_constants() const {
  return Eigen::Vector2d(-1.0 / eigenvalues_[0], -1.0 / eigenvalues_[1]);
}

}  // namespace tendril::physics
