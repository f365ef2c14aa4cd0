#include "tendril/dynamics/sequence_data.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

void SequenceData::validate() const {
  const int64_t n = rows();
  require(n >= 1, "has no rows", source);
  require(states.rows() == n && inputs.rows() == n && static_cast<int64_t>(split.size()) == n,
          "time, states, inputs and split have different numbers of rows", source);
  require(static_cast<int64_t>(state_names.size()) == states.cols() &&
              static_cast<int64_t>(input_names.size()) == inputs.cols(),
          "column names do not match the state and input columns", source);
  require(states.cols() >= 1, "has no state columns", source);
  for (int64_t t = 0; t < n; ++t) {
    if (!std::isfinite(time(t)) || !states.row(t).allFinite() || !inputs.row(t).allFinite()) {
      throw Error("non-finite value in row " + std::to_string(t), source);
    }
  }
}

double SequenceData::sample_period() const {
  std::vector<double> steps;
  for (int64_t t = 1; t < rows(); ++t) {
    const double dt = time(t) - time(t - 1);
    if (dt > 0.0) steps.push_back(dt);
  }
  require(!steps.empty(), "needs at least two rows with increasing time stamps", source);
  const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
  std::nth_element(steps.begin(), middle, steps.end());
  return *middle;
}

std::vector<Segment> SequenceData::segments(double max_gap) const {
  std::vector<Segment> result;
  if (rows() == 0) return result;
  Segment current{0, 1, split[0]};
  for (int64_t t = 1; t < rows(); ++t) {
    const double dt = time(t) - time(t - 1);
    if (split[t] != current.split || !(dt > 0.0) || dt > max_gap) {
      result.push_back(current);
      current = Segment{t, t + 1, split[t]};
    } else {
      current.end = t + 1;
    }
  }
  result.push_back(current);
  return result;
}

}  // namespace tendril::dynamics
