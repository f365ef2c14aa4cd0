#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace tendril::envs {

// Running per-component mean and variance of a stream of vectors, combined with the parallel
// algorithm of Chan, Golub & LeVeque (1979) exactly as Stable-Baselines3's RunningMeanStd
// (stable_baselines3/common/running_mean_std.py): start from mean 0, variance 1 and a pseudo-
// count of 1e-4, and merge each batch by
//
//   δ = mean_b − mean,  n = count + count_b,  mean' = mean + δ count_b / n,
//   var' = (var count + var_b count_b + δ² count count_b / n) / n.
//
// Double precision, as SB3's float64 arrays. It also applies SB3 VecNormalize's two maps from
// raw to normalized values, so every normalizer shares one implementation of them.
class RunningMeanStd {
 public:
  static constexpr double kInitialCount = 1e-4;

  explicit RunningMeanStd(int size = 1);

  void update(const Eigen::VectorXd& sample);  // a batch of one
  // SB3's update(arr): the rows of `samples` are one batch of count_b = rows samples, with
  // mean_b and var_b their population mean and variance (ddof 0) per component.
  void update_batch(const Eigen::Ref<const Eigen::MatrixXd>& samples);
  void update_from_moments(const Eigen::VectorXd& batch_mean, const Eigen::VectorXd& batch_var,
                           double batch_count);
  // Folds in statistics gathered elsewhere (another environment's copy).
  void merge(const RunningMeanStd& other);

  int size() const { return static_cast<int>(mean_.size()); }
  const Eigen::VectorXd& mean() const { return mean_; }
  const Eigen::VectorXd& var() const { return var_; }
  double count() const { return count_; }

  // SB3's VecNormalize._normalize_obs: clip((x − mean) / sqrt(var + epsilon), −clip, clip).
  Eigen::VectorXd normalize(const Eigen::VectorXd& x, double epsilon, double clip) const;
  // SB3's VecNormalize.normalize_reward, on one-component statistics of the discounted return:
  // clip(x / sqrt(var + epsilon), −clip, clip) — scaled, not centred, so the sign is kept.
  double scale(double x, double epsilon, double clip) const;

  // Plain numbers for a checkpoint: [count, mean_0 … mean_{n−1}, var_0 … var_{n−1}].
  std::vector<double> to_array() const;
  // Inverse of to_array; raises Error unless `values` has 1 + 2·size entries, a positive count,
  // finite means and non-negative finite variances.
  static RunningMeanStd from_array(std::span<const double> values, int size);

  bool operator==(const RunningMeanStd&) const = default;

 private:
  Eigen::VectorXd mean_;
  Eigen::VectorXd var_;
  double count_ = kInitialCount;
};

}  // namespace tendril::envs
