#include "tendril/dynamics/sequence_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

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
  require(lines.empty() || static_cast<int64_t>(lines.size()) == n,
          "line numbers and rows differ in count", source);
  for (int64_t t = 0; t < n; ++t) {
    if (!std::isfinite(time(t)) || !states.row(t).allFinite() || !inputs.row(t).allFinite()) {
      throw Error("non-finite value", where(t));
    }
  }
}

std::string SequenceData::where(int64_t t) const {
  if (t >= 0 && t < static_cast<int64_t>(lines.size())) {
    return source + ":" + std::to_string(lines[static_cast<std::size_t>(t)]);
  }
  return source + ", row " + std::to_string(t);
}

namespace {

std::string seconds(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", value);
  return text;
}

}  // namespace

std::string SequenceData::describe_runs(Split wanted, int64_t rows_needed, double max_gap) const {
  const char* name = wanted == Split::kTrain ? "train" : "test";
  int64_t longest = 0, longest_begin = -1, backward = 0, jumps = 0;
  int64_t first_backward = -1, first_jump = -1;
  for (const Segment& segment : segments(max_gap)) {
    if (segment.split != wanted) continue;
    if (segment.size() > longest) longest = segment.size(), longest_begin = segment.begin;
    if (segment.begin == 0 || split[segment.begin - 1] != wanted) continue;
    const double dt = time(segment.begin) - time(segment.begin - 1);
    if (!(dt > 0.0)) {
      if (backward++ == 0) first_backward = segment.begin;
    } else if (jumps++ == 0) {
      first_jump = segment.begin;
    }
  }
  if (longest == 0) return std::string("it has no ") + name + " rows";
  std::string text = std::string("its longest run of ") + name +
                     " rows with time stamps increasing by at most " + seconds(max_gap) + " has " +
                     std::to_string(longest) + " rows (from " + where(longest_begin) +
                     "), a window needs " + std::to_string(rows_needed);
  if (backward > 0) {
    text += "; time stands still or goes back " + std::to_string(backward) + " times (first at " +
            where(first_backward) + ": rows out of order?)";
  }
  if (jumps > 0) {
    text += "; time jumps by more than " + seconds(max_gap) + " " + std::to_string(jumps) +
            " times (first at " + where(first_jump) + ")";
  }
  return text;
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
