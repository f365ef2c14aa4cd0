#pragma once

#include <string>
#include <vector>

#include "tendril/dynamics/architecture.hpp"
#include "tendril/dynamics/normalizer.hpp"

namespace tendril::dynamics {

// What a trained model is, apart from its weights: the network's shape, the columns it reads and
// predicts, how it normalises them, and the data's sampling period. Stored in the model file.
// Torch-free, so that model files can be read (and fuzzed) without LibTorch.
struct ModelDescription {
  ArchitectureSpec architecture;
  Normalizer normalizer;  // columns of a row [x, u]
  std::vector<std::string> state_names;
  std::vector<std::string> input_names;
  double sample_period = 0.0;  // seconds

  // Raises Error naming `where` unless the parts agree with each other.
  void validate(const std::string& where) const;
};

}  // namespace tendril::dynamics
