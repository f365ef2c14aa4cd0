#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// Several outputs over the same inputs, each an independent GaussianProcess with its own
// hyper-parameters (same kernel type and options). Targets are rows (n × output_dim), like the
// inputs (n × input_dim).
class MultiOutputGp {
 public:
  MultiOutputGp(int input_dim, int output_dim, GpOptions options = {});

  void fit(const Eigen::Ref<const Eigen::MatrixXd>& inputs,
           const Eigen::Ref<const Eigen::MatrixXd>& targets);
  // Appends one point to every output (the window, if any, drops the oldest).
  void add(const Eigen::Ref<const Eigen::VectorXd>& input,
           const Eigen::Ref<const Eigen::VectorXd>& target);
  void remove_oldest();
  void clear();

  // Fits each output's hyper-parameters (GaussianProcess::optimize_hyperparameters) with its own
  // stream seeded from `rng`. Returns the sum of the outputs' log marginal likelihoods.
  double optimize_hyperparameters(Rng& rng);

  // Mean and variance per query row and output (queries × output_dim).
  void predict(const Eigen::Ref<const Eigen::MatrixXd>& inputs, Eigen::MatrixXd& mean,
               Eigen::MatrixXd& variance, bool with_noise = false) const;

  int size() const { return outputs_.front().size(); }
  int input_dim() const { return outputs_.front().input_dim(); }
  int output_dim() const { return static_cast<int>(outputs_.size()); }
  const GaussianProcess& output(int k) const { return outputs_.at(k); }
  GaussianProcess& output(int k) { return outputs_.at(k); }

 private:
  std::vector<GaussianProcess> outputs_;
};

}  // namespace tendril::adapt
