#include "tendril/physics/contact/soft_wall.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics {

void SoftWall::validate(const char* who) const {
  require(std::isfinite(stiffness) && stiffness > 0.0, "wall stiffness must be finite and positive",
          who);
  require(std::isfinite(damping) && damping >= 0.0, "wall damping must be finite and non-negative",
          who);
}

}  // namespace tendril::physics
