#pragma once

#include <Eigen/Core>

#include "tendril/dynamics/architecture.hpp"
#include "tendril/dynamics/sequence_data.hpp"

namespace tendril::dynamics {

// The affine map of each column of a row [x, u] onto the network's scale:
// v_normalised = (v − offset) / scale, column by column. Fitted once on the training rows and
// stored with the model, so a model normalises what it is given exactly as in training.
struct Normalizer {
  Eigen::VectorXd offset;  // one per column of [x, u]
  Eigen::VectorXd scale;   // positive

  // Identity map for `size` columns.
  static Normalizer identity(int size);
  // From the rows of `data` in the train split. A constant column keeps scale 1.
  static Normalizer fit(const SequenceData& data, Normalization kind);

  int size() const { return static_cast<int>(offset.size()); }
  // Raises Error naming `where` unless offsets are finite and scales finite and positive.
  void validate(int expected_size, const std::string& where) const;
};

}  // namespace tendril::dynamics
