#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace tendril::nn {

// Adam (Kingma & Ba 2015, Algorithm 1) on a flat float parameter vector, with
// torch::optim::Adam's arithmetic (no weight decay, no AMSGrad) so results match SB3's:
//   m ← β₁ m + (1 − β₁) g,   v ← β₂ v + (1 − β₂) g²
//   θ ← θ − (lr / (1 − β₁ᵗ)) · m / (√v / √(1 − β₂ᵗ) + ε)
class Adam {
 public:
  struct Options {
    double learning_rate = 1e-3;
    double beta1 = 0.9;
    double beta2 = 0.999;
    double epsilon = 1e-8;
  };

  Adam() = default;
  Adam(int64_t parameter_count, const Options& options);

  // One update of `parameters` from `gradient`.
  void step(Eigen::Ref<Eigen::VectorXf> parameters,
            const Eigen::Ref<const Eigen::VectorXf>& gradient);

  double learning_rate() const { return options_.learning_rate; }
  void set_learning_rate(double learning_rate) { options_.learning_rate = learning_rate; }

  // The state needed to continue (steps and both moments), for checkpoints.
  int64_t steps() const { return steps_; }
  const Eigen::VectorXf& first_moment() const { return first_moment_; }
  const Eigen::VectorXf& second_moment() const { return second_moment_; }
  // Raises Error when the moments do not fit this optimizer's parameter count.
  void set_state(int64_t steps, const Eigen::VectorXf& first_moment,
                 const Eigen::VectorXf& second_moment);

 private:
  Options options_;
  int64_t steps_ = 0;
  Eigen::VectorXf first_moment_, second_moment_;
};

}  // namespace tendril::nn
