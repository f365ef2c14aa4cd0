#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "tendril/core/rng.hpp"

namespace tendril {

// Observations and actions cross the learning boundary as contiguous float vectors, so a batch
// of them maps onto a tensor or a NumPy array without a copy. A Discrete action is a vector of
// size one holding the index.
using Observation = Eigen::VectorXf;
using Action = Eigen::VectorXf;

// A Box (per-component bounds, possibly infinite) or Discrete(n) space, with Gymnasium's meaning.
class Space {
 public:
  enum class Kind { kBox, kDiscrete };

  static Space box(Eigen::VectorXf low, Eigen::VectorXf high);
  static Space box(int size, float low, float high);
  static Space discrete(int64_t n);

  Kind kind() const { return kind_; }
  bool is_box() const { return kind_ == Kind::kBox; }
  bool is_discrete() const { return kind_ == Kind::kDiscrete; }

  // Components of a vector drawn from this space (1 for Discrete).
  int size() const { return kind_ == Kind::kBox ? static_cast<int>(low_.size()) : 1; }
  int64_t n() const { return n_; }  // Discrete only
  const Eigen::VectorXf& low() const { return low_; }
  const Eigen::VectorXf& high() const { return high_; }
  bool bounded() const;  // every bound finite

  bool contains(const Eigen::VectorXf& x) const;
  // Uniform in a bounded box, standard normal along unbounded directions (Gymnasium's rule).
  Eigen::VectorXf sample(Rng& rng) const;

  std::string describe() const;  // "Box(12, [-1, 1])", "Discrete(2)"

 private:
  Kind kind_ = Kind::kBox;
  Eigen::VectorXf low_, high_;
  int64_t n_ = 0;
};

}  // namespace tendril
