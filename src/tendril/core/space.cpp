#include "tendril/core/space.hpp"

#include <cmath>
#include <sstream>

#include "tendril/core/error.hpp"

namespace tendril {

Space Space::box(Eigen::VectorXf low, Eigen::VectorXf high) {
  require(low.size() == high.size(), "Box bounds differ in size", "Space::box");
  require(low.size() > 0, "Box must have at least one component", "Space::box");
  for (Eigen::Index i = 0; i < low.size(); ++i) {
    require(!std::isnan(low[i]) && !std::isnan(high[i]) && low[i] <= high[i],
            "Box bound " + std::to_string(i) + " is NaN or low > high", "Space::box");
  }
  Space space;
  space.kind_ = Kind::kBox;
  space.low_ = std::move(low);
  space.high_ = std::move(high);
  return space;
}

Space Space::box(int size, float low, float high) {
  return box(Eigen::VectorXf::Constant(size, low), Eigen::VectorXf::Constant(size, high));
}

Space Space::discrete(int64_t n) {
  require(n >= 1, "Discrete space needs n >= 1, got " + std::to_string(n), "Space::discrete");
  Space space;
  space.kind_ = Kind::kDiscrete;
  space.n_ = n;
  return space;
}

bool Space::bounded() const {
  return kind_ == Kind::kDiscrete || (low_.array().isFinite().all() && high_.array().isFinite().all());
}

bool Space::contains(const Eigen::VectorXf& x) const {
  if (x.size() != size() || !x.allFinite()) return false;
  if (kind_ == Kind::kDiscrete) {
    return x[0] >= 0 && x[0] < static_cast<float>(n_) && x[0] == std::floor(x[0]);
  }
  return (x.array() >= low_.array()).all() && (x.array() <= high_.array()).all();
}

Eigen::VectorXf Space::sample(Rng& rng) const {
  if (kind_ == Kind::kDiscrete) {
    return Eigen::VectorXf::Constant(1, static_cast<float>(rng.below(static_cast<uint64_t>(n_))));
  }
  Eigen::VectorXf x(low_.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const bool low_finite = std::isfinite(low_[i]);
    const bool high_finite = std::isfinite(high_[i]);
    if (low_finite && high_finite) {
      x[i] = static_cast<float>(rng.uniform(low_[i], high_[i]));
    } else if (low_finite) {
      x[i] = low_[i] - static_cast<float>(std::log(1.0 - rng.uniform()));  // exponential
    } else if (high_finite) {
      x[i] = high_[i] + static_cast<float>(std::log(1.0 - rng.uniform()));
    } else {
      x[i] = static_cast<float>(rng.normal());
    }
  }
  return x;
}

std::string Space::describe() const {
  std::ostringstream text;
  if (kind_ == Kind::kDiscrete) {
    text << "Discrete(" << n_ << ")";
  } else {
    text << "Box(" << low_.size() << ", [" << low_.minCoeff() << ", " << high_.maxCoeff() << "])";
  }
  return text.str();
}

}  // namespace tendril
