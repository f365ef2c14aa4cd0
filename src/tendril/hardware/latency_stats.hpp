#pragma once

#include <vector>

namespace tendril::hardware {

// Round-trip times of a link (s): count, mean, median, 95th percentile, maximum, and jitter
// as the standard deviation.
class LatencyStats {
 public:
  void add(double seconds) { samples_.push_back(seconds); }
  int count() const { return static_cast<int>(samples_.size()); }
  double mean() const;
  double percentile(double p) const;  // p in [0, 100]; 0 without samples
  double max() const;
  double jitter() const;
  void clear() { samples_.clear(); }

 private:
  std::vector<double> samples_;
};

}  // namespace tendril::hardware
