#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace tendril::envs::sma_limb {

// Visit counts of the bend-angle plane on a grid of cells_per_axis² cells over
// [−limit, limit]² (deg); angles outside count in the edge cells. The thesis' exploration used
// 6 × 6 cells over ±100° (seed 001, Alg. 1; spec §2.2). Cell index = row · n + column, the
// column along θx.
class VisitGrid {
 public:
  explicit VisitGrid(int cells_per_axis = 6, double limit_deg = 100.0);

  int cells() const { return static_cast<int>(counts_.size()); }
  int cells_per_axis() const { return per_axis_; }
  int cell(const Eigen::Vector2d& angles_deg) const;
  Eigen::Vector2d centre(int cell) const;
  void visit(const Eigen::Vector2d& angles_deg);
  const std::vector<int64_t>& counts() const { return counts_; }
  int64_t max_count() const { return max_count_; }
  int64_t total() const { return total_; }

  // Coverage measures: the number of cells visited at least once, and the evenness of the
  // visits — the Shannon entropy of their distribution over the cells divided by its largest
  // value, log(cells): 1 when every cell is visited equally often, 0 when one cell has them all.
  int visited_cells() const;
  double evenness() const;

 private:
  int per_axis_;
  double limit_;
  std::vector<int64_t> counts_;
  int64_t max_count_ = 0, total_ = 0;
};

}  // namespace tendril::envs::sma_limb
