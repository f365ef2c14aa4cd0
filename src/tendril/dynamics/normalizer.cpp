#include "tendril/dynamics/normalizer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

Normalizer Normalizer::identity(int size) {
  return Normalizer{Eigen::VectorXd::Zero(size), Eigen::VectorXd::Ones(size)};
}

namespace {

// `fitted` when its offsets and scales are finite; otherwise an Error naming the column, its
// largest training value and the file and line it is on (a sum or a square overflowed).
Normalizer checked(const Normalizer& fitted, const SequenceData& data) {
  for (int c = 0; c < static_cast<int>(fitted.offset.size()); ++c) {
    if (std::isfinite(fitted.offset(c)) && std::isfinite(fitted.scale(c))) continue;
    const bool state = c < data.state_dim();
    const int column = state ? c : c - data.state_dim();
    const auto values = state ? data.states.col(column) : data.inputs.col(column);
    int64_t largest = -1;
    for (int64_t t = 0; t < data.rows(); ++t) {
      if (data.split[t] != Split::kTrain) continue;
      if (largest < 0 || std::abs(values(t)) > std::abs(values(largest))) largest = t;
    }
    char value[32];
    std::snprintf(value, sizeof value, "%g", values(largest));
    throw Error("column '" + (state ? data.state_names : data.input_names)[column] +
                    "': its values are too large to normalise (their mean or spread overflows); "
                    "the largest, " +
                    value + ", is on this line",
                data.where(largest));
  }
  return fitted;
}

}  // namespace

Normalizer Normalizer::fit(const SequenceData& data, Normalization kind) {
  const int columns = data.state_dim() + data.input_dim();
  Normalizer result = identity(columns);
  if (kind == Normalization::kNone) return result;
  auto value = [&](int64_t t, int c) {
    return c < data.state_dim() ? data.states(t, c) : data.inputs(t, c - data.state_dim());
  };
  int64_t count = 0;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(columns), low, high;
  low = Eigen::VectorXd::Constant(columns, INFINITY);
  high = Eigen::VectorXd::Constant(columns, -INFINITY);
  for (int64_t t = 0; t < data.rows(); ++t) {
    if (data.split[t] != Split::kTrain) continue;
    ++count;
    for (int c = 0; c < columns; ++c) {
      sum(c) += value(t, c);
      low(c) = std::min(low(c), value(t, c));
      high(c) = std::max(high(c), value(t, c));
    }
  }
  require(count >= 2, "needs at least two training rows to normalise", data.source);
  if (kind == Normalization::kMinMax) {
    for (int c = 0; c < columns; ++c) {
      result.offset(c) = 0.5 * (high(c) + low(c));
      if (high(c) > low(c)) result.scale(c) = 0.5 * (high(c) - low(c));
    }
    return checked(result, data);
  }
  const Eigen::VectorXd mean = sum / static_cast<double>(count);
  Eigen::VectorXd squares = Eigen::VectorXd::Zero(columns);
  for (int64_t t = 0; t < data.rows(); ++t) {
    if (data.split[t] != Split::kTrain) continue;
    for (int c = 0; c < columns; ++c) squares(c) += std::pow(value(t, c) - mean(c), 2);
  }
  for (int c = 0; c < columns; ++c) {
    result.offset(c) = mean(c);
    const double deviation = std::sqrt(squares(c) / static_cast<double>(count));
    if (deviation > 0.0) result.scale(c) = deviation;
  }
  return checked(result, data);
}

void Normalizer::validate(int expected_size, const std::string& where) const {
  require(offset.size() == expected_size && scale.size() == expected_size,
          "normalisation has " + std::to_string(offset.size()) + " columns, the model " +
              std::to_string(expected_size),
          where);
  require(offset.allFinite() && scale.allFinite() && (scale.array() > 0.0).all(),
          "normalisation offsets must be finite and scales finite and positive", where);
}

}  // namespace tendril::dynamics
