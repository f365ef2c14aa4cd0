#include "tendril/envs/sma_limb/visit_grid.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::sma_limb {

VisitGrid::VisitGrid(int cells_per_axis, double limit_deg)
    : per_axis_(cells_per_axis), limit_(limit_deg) {
  require(cells_per_axis >= 1 && std::isfinite(limit_deg) && limit_deg > 0.0,
          "a visit grid needs at least one cell per axis and a positive limit", "VisitGrid");
  counts_.assign(static_cast<std::size_t>(cells_per_axis * cells_per_axis), 0);
}

int VisitGrid::cell(const Eigen::Vector2d& angles_deg) const {
  const double width = 2.0 * limit_ / per_axis_;
  auto index = [&](double angle) {
    const int i = static_cast<int>(std::floor((angle + limit_) / width));
    return std::clamp(i, 0, per_axis_ - 1);
  };
  return index(angles_deg.y()) * per_axis_ + index(angles_deg.x());
}

Eigen::Vector2d VisitGrid::centre(int cell) const {
  const double width = 2.0 * limit_ / per_axis_;
  return Eigen::Vector2d(-limit_ + (cell % per_axis_ + 0.5) * width,
                         -limit_ + (cell / per_axis_ + 0.5) * width);
}

void VisitGrid::visit(const Eigen::Vector2d& angles_deg) {
  int64_t& count = counts_[static_cast<std::size_t>(cell(angles_deg))];
  ++count;
  ++total_;
  max_count_ = std::max(max_count_, count);
}

int VisitGrid::visited_cells() const {
  return static_cast<int>(
      std::count_if(counts_.begin(), counts_.end(), [](int64_t count) { return count > 0; }));
}

double VisitGrid::evenness() const {
  if (total_ == 0 || cells() == 1) return 0.0;
  double entropy = 0.0;
  for (int64_t count : counts_) {
    if (count == 0) continue;
    const double p = static_cast<double>(count) / static_cast<double>(total_);
    entropy -= p * std::log(p);
  }
  return entropy / std::log(static_cast<double>(cells()));
}

}  // namespace tendril::envs::sma_limb
