#include "tendril/adapt/coach.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

constexpr const char* kWhere = "adapt::coach_path";

}  // namespace

Eigen::MatrixXd coach_path(const std::vector<Eigen::MatrixXd>& trajectories,
                           const Eigen::Vector3d& goal, double radius, const CoachOptions& options,
                           Rng& rng) {
  require(std::isfinite(radius) && radius > 0.0, "the radius must be positive", kWhere);
  require(options.time_weight >= 0.0 && options.min_visit_fraction >= 0.0 &&
              options.min_visit_fraction <= 1.0,
          "time_weight must be non-negative and min_visit_fraction within [0, 1]", kWhere);
  std::vector<Eigen::MatrixXd> cut;
  for (const Eigen::MatrixXd& trajectory : trajectories) {
    require(trajectory.cols() > 0 && trajectory.cols() % 3 == 0,
            "states must be triples of coordinates (one per module)", kWhere);
    require(trajectory.allFinite(), "trajectories must be finite", kWhere);
    for (Eigen::Index t = 0; t < trajectory.rows(); ++t) {
      const Eigen::Vector3d point = trajectory.row(t).tail<3>().transpose();
      if ((point - goal).norm() <= radius) {
        cut.push_back(trajectory.topRows(t + 1));
        break;
      }
    }
  }
  require(!cut.empty(), "no trajectory comes within " + std::to_string(radius) + " of the goal",
          kWhere);
  const int dims = static_cast<int>(cut.front().cols());
  const int modules = dims / 3;
  double total = 0.0;
  for (const Eigen::MatrixXd& c : cut) total += static_cast<double>(c.rows());
  const int points = static_cast<int>(total);
  const int length =
      std::max(1, static_cast<int>(std::lround(total / static_cast<double>(cut.size()))));

  KMeansOptions kmeans_options = options.kmeans;
  kmeans_options.clusters = std::min(length, points);
  Eigen::MatrixXd path(kmeans_options.clusters, dims);
  std::vector<int> owner(points);  // the trajectory of every point
  std::vector<double> kept_fraction;
  for (int module = 0; module < modules; ++module) {
    Eigen::MatrixXd features(points, 4);
    int row = 0;
    for (std::size_t n = 0; n < cut.size(); ++n) {
      for (Eigen::Index t = 0; t < cut[n].rows(); ++t, ++row) {
        features.row(row).head<3>() = cut[n].row(t).segment<3>(3 * module);
        features(row, 3) = options.time_weight * static_cast<double>(t);
        owner[row] = static_cast<int>(n);
      }
    }
    const KMeansResult clusters = kmeans(features, kmeans_options, rng);
    // Order by mean time: the time feature's centroid coordinate (or, without a time weight,
    // the mean step index of the members).
    std::vector<double> mean_time(kmeans_options.clusters, 0.0);
    std::vector<int> members(kmeans_options.clusters, 0);
    row = 0;
    for (const Eigen::MatrixXd& c : cut) {
      for (Eigen::Index t = 0; t < c.rows(); ++t, ++row) {
        mean_time[clusters.labels[row]] += static_cast<double>(t);
        ++members[clusters.labels[row]];
      }
    }
    std::vector<int> order(kmeans_options.clusters);
    std::iota(order.begin(), order.end(), 0);
    for (int k = 0; k < kmeans_options.clusters; ++k) {
      mean_time[k] = members[k] > 0 ? mean_time[k] / members[k] : 1e300;
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return mean_time[a] < mean_time[b]; });
    for (int i = 0; i < kmeans_options.clusters; ++i) {
      path.row(i).segment<3>(3 * module) = clusters.centroids.row(order[i]).head<3>();
    }
    if (module == modules - 1) {
      std::vector<std::set<int>> visitors(kmeans_options.clusters);
      for (int p = 0; p < points; ++p) visitors[clusters.labels[p]].insert(owner[p]);
      for (int i = 0; i < kmeans_options.clusters; ++i) {
        kept_fraction.push_back(static_cast<double>(visitors[order[i]].size()) /
                                static_cast<double>(cut.size()));
      }
    }
  }
  std::vector<int> rows;
  for (int i = 0; i < kmeans_options.clusters; ++i) {
    if (kept_fraction[i] >= options.min_visit_fraction) rows.push_back(i);
  }
  require(!rows.empty(), "every cluster of the coach's path is visited too rarely", kWhere);
  Eigen::MatrixXd kept(rows.size(), dims);
  for (std::size_t i = 0; i < rows.size(); ++i) kept.row(i) = path.row(rows[i]);
  return kept;
}

}  // namespace tendril::adapt
