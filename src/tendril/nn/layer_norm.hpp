#pragma once

#include <Eigen/Core>

namespace tendril::nn {

// Layer normalisation without a learned gain or bias (Ba et al. 2016, eq. 4, with γ = 1 and
// β = 0): each column x of n features becomes y = (x − mean(x)) / sqrt(var(x) + ε), var the
// biased variance, as torch.nn.LayerNorm(n, elementwise_affine=False) computes it. Seed 001
// normalises a policy head's output this way before actor and critics read it (thesis §5.1.2);
// the first layer of each reader can scale and shift the features, so no gain or bias is
// learned here.
class LayerNorm {
 public:
  // What the backward pass needs: the output and 1 / sqrt(var + ε) per column.
  struct Tape {
    Eigen::MatrixXf output;
    Eigen::RowVectorXf inverse_std;
  };

  explicit LayerNorm(float epsilon = 1e-5f) : epsilon_(epsilon) {}

  // inputs: features × batch.
  void forward(const Eigen::Ref<const Eigen::MatrixXf>& inputs, Tape& tape) const;
  // ∂L/∂x from ∂L/∂y (features × batch) of the pass in `tape`, per column:
  //   ∂L/∂x = (g − mean(g) − y · mean(g ⊙ y)) / sqrt(var + ε),   g = ∂L/∂y.
  void backward(const Tape& tape, const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                Eigen::MatrixXf& input_gradient) const;

 private:
  float epsilon_;
};

}  // namespace tendril::nn
