#pragma once

#include <cmath>
#include <numbers>
#include <utility>

#include "tendril/physics/forcing/active_strain.hpp"
#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/rod/rod.hpp"
#include "tendril/physics/rod/rod_jacobian.hpp"

namespace tendril::physics::testing {

// Analytical damping that decays every translational and rotational rate of a uniform rod at
// `rate` (1/s): γ_t = rate·ρA, γ_r = rate·ρI.
inline RodPart& add_uniform_damping(Rod& rod, double rate) {
  const double area = std::numbers::pi * rod.model().rest_radii[0] * rod.model().rest_radii[0];
  const double i1 = area * area / (4.0 * std::numbers::pi);
  return rod.add<AnalyticalLinearDamping>(rate * rod.model().density * area,
                                          rate * rod.model().density * i1);
}

// Advances in chunks until the fastest node moves slower than `speed_tolerance` (m/s), or
// `max_time` seconds pass. Returns true if it settled with a finite state.
inline bool settle(Rod& rod, double max_time, double speed_tolerance) {
  const int chunk = std::max(1, static_cast<int>(0.01 / rod.time_step()));
  while (rod.time() < max_time) {
    if (!rod.advance(chunk)) return false;
    if (rod.state().velocities.colwise().norm().maxCoeff() < speed_tolerance) return true;
  }
  return false;
}

constexpr double kBetaL = 1.8751040687;  // first root of 1 + cos βL cosh βL = 0

// The first clamped-free mode shape of an Euler–Bernoulli beam, and its slope.
inline double mode_shape(double x, double beta) {
  const double b = kBetaL;
  const double sigma = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
  return std::cosh(beta * x) - std::cos(beta * x) -
         sigma * (std::sinh(beta * x) - std::sin(beta * x));
}
inline double mode_slope(double x, double beta) {
  const double b = kBetaL;
  const double sigma = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
  return beta * (std::sinh(beta * x) + std::sin(beta * x) -
                 sigma * (std::cosh(beta * x) - std::cos(beta * x)));
}

// Sets a clamped rod along x (d1 = y, d2 = z) vibrating in (nearly) its first mode alone: node
// velocities V φ(x) along y and element rotation rates V φ'(x) about d2, V the tip's speed.
inline void start_first_mode(Rod& rod, double tip_speed) {
  const double length = rod.model().rest_lengths.sum();
  const double beta = kBetaL / length;
  const double scale = tip_speed / mode_shape(length, beta);
  RodState& state = rod.mutable_state();
  for (int j = 0; j <= rod.n_elements(); ++j) {
    state.velocities(1, j) = scale * mode_shape(state.positions(0, j), beta);
  }
  for (int i = 0; i < rod.n_elements(); ++i) {
    const double middle = 0.5 * (state.positions(0, i) + state.positions(0, i + 1));
    state.angular_velocities(1, i) = scale * mode_slope(middle, beta);
  }
  rod.state_changed();
}

// A constant active strain (what the pneumatic chambers impose), with its load derivatives for
// the implicit steppers.
class ConstantActiveStrain final : public RodPart {
 public:
  ConstantActiveStrain(Vectors stretch, Vectors curvature)
      : stretch_(std::move(stretch)), curvature_(std::move(curvature)) {}
  uint32_t stages() const override { return kLoads; }
  void attach(const RodModel& model, const RodState&) override { loads_.resize(model); }
  void add_loads(const RodModel& model, RodState& state) override {
    loads_.add(model, state, stretch_, curvature_);
  }
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override {
    loads_.add_derivatives(model, state, jacobian);
  }

 private:
  Vectors stretch_, curvature_;
  ActiveStrainLoads loads_;
};

}  // namespace tendril::physics::testing
