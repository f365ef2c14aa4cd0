#include "tendril/physics/lattice/lattice_model.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

void LatticeModel::validate(const std::string& where) const {
  const int n = n_nodes();
  require(n >= 1, "a lattice needs at least one node", where);
  require(rest_positions.allFinite(), "rest_positions must be finite", where);
  if (masses.size() != n || static_cast<int>(fixed.size()) != n) {
    throw Error("masses (" + std::to_string(masses.size()) + ") and fixed (" +
                    std::to_string(fixed.size()) + ") must have one entry per node (" +
                    std::to_string(n) + ")",
                where);
  }
  for (int i = 0; i < n; ++i) {
    if (!fixed[i] && !(std::isfinite(masses[i]) && masses[i] > 0.0)) {
      throw Error("mass of free node " + std::to_string(i) + " must be finite and positive, got " +
                      std::to_string(masses[i]),
                  where);
    }
  }
  if (!(std::isfinite(mass_damping) && mass_damping >= 0.0)) {
    throw Error("mass_damping must be finite and non-negative, got " + std::to_string(mass_damping),
                where);
  }
  for (int s = 0; s < n_springs(); ++s) {
    const Spring& spring = springs[s];
    const std::string name = "spring " + std::to_string(s);
    if (spring.a < 0 || spring.a >= n || spring.b < 0 || spring.b >= n || spring.a == spring.b) {
      throw Error(name + " joins nodes " + std::to_string(spring.a) + " and " +
                      std::to_string(spring.b) + ", not two distinct nodes of " + std::to_string(n),
                  where);
    }
    if (!(std::isfinite(spring.rest_length) && spring.rest_length > 0.0)) {
      throw Error(name + " rest_length must be finite and positive", where);
    }
    if (!(std::isfinite(spring.stiffness) && spring.stiffness >= 0.0)) {
      throw Error(name + " stiffness must be finite and non-negative", where);
    }
    if (!(std::isfinite(spring.damping) && spring.damping >= 0.0)) {
      throw Error(name + " damping must be finite and non-negative", where);
    }
  }
}

}  // namespace tendril::physics
