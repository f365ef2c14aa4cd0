#include "tendril/rl/algorithm.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

void check_observations(const envs::BatchMatrix& observations, int size, const std::string& where) {
  require(observations.cols() == size,
          "observations have " + std::to_string(observations.cols()) + " components, expected " +
              std::to_string(size),
          where);
  require(observations.allFinite(), "observations are not finite", where);
}

}  // namespace tendril::rl
