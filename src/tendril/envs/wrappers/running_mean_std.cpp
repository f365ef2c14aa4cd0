#include "tendril/envs/wrappers/running_mean_std.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs {

RunningMeanStd::RunningMeanStd(int size)
    : mean_(Eigen::VectorXd::Zero(size)), var_(Eigen::VectorXd::Ones(size)) {
  require(size >= 1, "size must be at least 1, got " + std::to_string(size),
          "envs::RunningMeanStd");
}

void RunningMeanStd::update(const Eigen::VectorXd& sample) {
  update_from_moments(sample, Eigen::VectorXd::Zero(sample.size()), 1.0);
}

void RunningMeanStd::update_batch(const Eigen::Ref<const Eigen::MatrixXd>& samples) {
  require(samples.rows() >= 1, "batch has no samples", "envs::RunningMeanStd");
  const Eigen::VectorXd batch_mean = samples.colwise().mean().transpose();
  const Eigen::VectorXd batch_var =
      (samples.rowwise() - batch_mean.transpose()).array().square().colwise().mean().transpose();
  update_from_moments(batch_mean, batch_var, static_cast<double>(samples.rows()));
}

void RunningMeanStd::update_from_moments(const Eigen::VectorXd& batch_mean,
                                         const Eigen::VectorXd& batch_var, double batch_count) {
  require(batch_mean.size() == mean_.size() && batch_var.size() == mean_.size(),
          "batch has " + std::to_string(batch_mean.size()) + " components, expected " +
              std::to_string(mean_.size()),
          "envs::RunningMeanStd");
  const Eigen::ArrayXd delta = (batch_mean - mean_).array();
  const double total = count_ + batch_count;
  const Eigen::ArrayXd m2 = var_.array() * count_ + batch_var.array() * batch_count +
                            delta.square() * count_ * batch_count / total;
  mean_ = (mean_.array() + delta * batch_count / total).matrix();
  var_ = (m2 / total).matrix();
  count_ = total;
}

Eigen::VectorXd RunningMeanStd::normalize(const Eigen::VectorXd& x, double epsilon,
                                          double clip) const {
  const Eigen::ArrayXd scaled = (x - mean_).array() / (var_.array() + epsilon).sqrt();
  return scaled.max(-clip).min(clip).matrix();
}

double RunningMeanStd::scale(double x, double epsilon, double clip) const {
  return std::clamp(x / std::sqrt(var_[0] + epsilon), -clip, clip);
}

void RunningMeanStd::merge(const RunningMeanStd& other) {
  update_from_moments(other.mean_, other.var_, other.count_);
}

std::vector<double> RunningMeanStd::to_array() const {
  std::vector<double> values;
  values.reserve(1 + 2 * mean_.size());
  values.push_back(count_);
  values.insert(values.end(), mean_.data(), mean_.data() + mean_.size());
  values.insert(values.end(), var_.data(), var_.data() + var_.size());
  return values;
}

RunningMeanStd RunningMeanStd::from_array(std::span<const double> values, int size) {
  const std::string where = "envs::RunningMeanStd::from_array";
  require(size >= 1 && values.size() == static_cast<std::size_t>(1 + 2 * size),
          "expected " + std::to_string(1 + 2 * size) + " numbers (count, " + std::to_string(size) +
              " means, " + std::to_string(size) + " variances), got " +
              std::to_string(values.size()),
          where);
  RunningMeanStd stats(size);
  stats.count_ = values[0];
  require(std::isfinite(stats.count_) && stats.count_ > 0.0, "count must be positive and finite",
          where);
  for (int i = 0; i < size; ++i) {
    stats.mean_[i] = values[1 + i];
    stats.var_[i] = values[1 + size + i];
    require(std::isfinite(stats.mean_[i]), "mean " + std::to_string(i) + " is not finite", where);
    require(std::isfinite(stats.var_[i]) && stats.var_[i] >= 0.0,
            "variance " + std::to_string(i) + " is negative or not finite", where);
  }
  return stats;
}

}  // namespace tendril::envs
