#include "tendril/hardware/latency_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tendril::hardware {

double LatencyStats::mean() const {
  if (samples_.empty()) return 0.0;
  return std::accumulate(samples_.begin(), samples_.end(), 0.0) / samples_.size();
}

double LatencyStats::percentile(double p) const {
  if (samples_.empty()) return 0.0;
  std::vector<double> sorted = samples_;
  std::sort(sorted.begin(), sorted.end());
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * (sorted.size() - 1);
  const size_t low = static_cast<size_t>(std::floor(rank));
  const size_t high = std::min(low + 1, sorted.size() - 1);
  return sorted[low] + (rank - low) * (sorted[high] - sorted[low]);
}

double LatencyStats::max() const {
  return samples_.empty() ? 0.0 : *std::max_element(samples_.begin(), samples_.end());
}

double LatencyStats::jitter() const {
  if (samples_.size() < 2) return 0.0;
  const double m = mean();
  double sum = 0.0;
  for (const double s : samples_) sum += (s - m) * (s - m);
  return std::sqrt(sum / (samples_.size() - 1));
}

}  // namespace tendril::hardware
