#include "tendril/envs/learned/dynamics_model.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs {

void DynamicsModel::step(HistoryWindows& windows, const BatchMatrix& inputs,
                         BatchMatrix& next_states) {
  if (windows.length() != window_length() || windows.state_dim() != state_dim() ||
      windows.input_dim() != input_dim()) {
    throw Error("windows of " + std::to_string(windows.length()) + " rows of " +
                    std::to_string(windows.state_dim()) + "+" +
                    std::to_string(windows.input_dim()) + " values do not fit a model of " +
                    std::to_string(window_length()) + " rows of " + std::to_string(state_dim()) +
                    "+" + std::to_string(input_dim()),
                "envs::DynamicsModel::step");
  }
  windows.set_inputs(inputs);
  predict(windows.windows(), next_states);
  windows.advance(next_states);
}

}  // namespace tendril::envs
