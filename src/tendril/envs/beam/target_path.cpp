#include "tendril/envs/beam/target_path.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::beam {

void Range::validate(const std::string& what, double min, double max) const {
  if (!(std::isfinite(low) && std::isfinite(high) && low <= high && low >= min && high <= max)) {
    throw Error("[" + std::to_string(low) + ", " + std::to_string(high) +
                    "] must be an interval within [" + std::to_string(min) + ", " +
                    std::to_string(max) + "]",
                what);
  }
}

void TargetPath::set_level(int level) {
  require(level >= 0 && level < levels(),
          "level " + std::to_string(level) + " is not one of the " + std::to_string(levels()) +
              " levels",
          "TargetPath::set_level");
  level_ = level;
}

}  // namespace tendril::envs::beam
