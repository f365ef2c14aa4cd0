#include "tendril/dynamics/model_description.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

void ModelDescription::validate(const std::string& where) const {
  try {
    architecture.validate();
  } catch (const Error& e) {
    throw Error("model." + e.where() + ": " + e.what_wrong(), where);
  }
  require(static_cast<int>(state_names.size()) == architecture.state_dim &&
              static_cast<int>(input_names.size()) == architecture.input_dim,
          "column names do not match the state and input sizes", where);
  normalizer.validate(architecture.row_size(), where);
  require(sample_period > 0.0 && std::isfinite(sample_period), "sample period must be positive",
          where);
}

}  // namespace tendril::dynamics
