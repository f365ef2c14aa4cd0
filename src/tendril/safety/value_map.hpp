#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tendril::safety {

// A co-training run's learned safety value over a grid of two coordinates of its SafetySearchSpace,
// the others held fixed (seed 001 Fig. 6.4: the double integrator's (x, ẋ) plane; Fig. 6.6: the
// limb's (θx, θy) with zero velocities): V_safe at t = 0, the safety policy's action and, where
// the environment has one, whether the state lies in the analytic safe set.
struct ValueMapOptions {
  int resolution = 101;  // points per axis
  double extent = 1.25;  // each axis spans ±extent normalized units (1 = the safe bound)
  int x_axis = 0, y_axis = 1;
  Eigen::VectorXd fixed;  // the other coordinates (normalized); empty: zeros
};

struct ValueMap {
  std::vector<std::string> columns;  // x name, y name, value, action_0.., [analytic_safe]
  Eigen::MatrixXd rows;              // one row per grid point, physical units
  bool has_analytic_set = false;

  // Of the grid points with V > epsilon (learned safe), the fraction outside the analytic set
  // (NaN without an analytic set or when no point is learned safe).
  double fraction_outside_analytic(double epsilon) const;
  // The grid as CSV with a header row.
  void write_csv(const std::filesystem::path& file) const;
};

ValueMap value_map_of_run(const std::filesystem::path& run_directory,
                          const ValueMapOptions& options);

}  // namespace tendril::safety
