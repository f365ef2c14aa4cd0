#pragma once

#include <cmath>
#include <numbers>

#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/rod/rod.hpp"

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

}  // namespace tendril::physics::testing
