#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// How the outputs' hyper-parameters are fitted:
//   per_output  each output maximises its own likelihood (input_dim + 2 parameters each)
//   shared      one set — length scales, and σ_f², σ_n² relative to each output's target
//               variance — maximises the summed likelihood of the standardised outputs
//               (scikit-learn's GaussianProcessRegressor with several target columns and
//               normalize_y); one factorisation per evaluation serves every output, so the search
//               costs what one output's does.
enum class HyperparameterSharing { per_output, shared };

// Several outputs over the same inputs, each an independent GaussianProcess (same kernel type
// and options). Targets are rows (n × output_dim), like the inputs (n × input_dim).
class MultiOutputGp {
 public:
  MultiOutputGp(int input_dim, int output_dim, GpOptions options = {},
                HyperparameterSharing sharing = HyperparameterSharing::per_output);

  void fit(const Eigen::Ref<const Eigen::MatrixXd>& inputs,
           const Eigen::Ref<const Eigen::MatrixXd>& targets);
  // Appends one point to every output (the window, if any, drops the oldest).
  void add(const Eigen::Ref<const Eigen::VectorXd>& input,
           const Eigen::Ref<const Eigen::VectorXd>& target);
  void remove_oldest();
  void clear();

  // Fits the hyper-parameters as `sharing` says: per output, each on its own stream seeded from
  // `rng`, or shared, starting from output 0's. Returns the sum of the outputs' log marginal
  // likelihoods.
  double optimize_hyperparameters(Rng& rng);

  // Mean and variance per query row and output (queries × output_dim).
  void predict(const Eigen::Ref<const Eigen::MatrixXd>& inputs, Eigen::MatrixXd& mean,
               Eigen::MatrixXd& variance, bool with_noise = false) const;

  int size() const { return outputs_.front().size(); }
  int input_dim() const { return outputs_.front().input_dim(); }
  int output_dim() const { return static_cast<int>(outputs_.size()); }
  const GaussianProcess& output(int k) const { return outputs_.at(k); }
  GaussianProcess& output(int k) { return outputs_.at(k); }
  HyperparameterSharing sharing() const { return sharing_; }

 private:
  double optimize_shared_hyperparameters(Rng& rng);

  std::vector<GaussianProcess> outputs_;
  HyperparameterSharing sharing_;
};

}  // namespace tendril::adapt
