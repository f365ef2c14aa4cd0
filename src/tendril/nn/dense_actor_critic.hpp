#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "tendril/nn/actor_critic.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/nn/flat_parameters.hpp"

namespace tendril::nn {

// An ActorCritic's `evaluate` and its gradient written out by hand (DenseMlp passes plus the
// distribution's derivatives), reading the weights from the flat buffer the module's
// parameters view (FlatParameters) and adding gradients into the matching flat gradient
// buffer. The module stays the owner of the parameters: checkpoints, TRPO and the inference
// copy see every update. For small control networks this replaces dozens of LibTorch calls
// per minibatch, each costing more in dispatch than its arithmetic.
//
// Batches are matrices with one column per sample: observations (observation_size × batch),
// actions (action_size × batch for a Gaussian; 1 × batch of choice indices, categorical).
class DenseActorCritic {
 public:
  // A forward pass and what its backward pass needs; reusing one for minibatches of the same
  // size does not allocate.
  struct Tape {
    // One network's pass, and its own backward workspace (so that shapes, hence
    // allocations, stay put from one minibatch to the next).
    struct Pass {
      DenseMlp::Tape tape;
      std::vector<Eigen::MatrixXf> scratch;
    };
    Pass policy_trunk, value_trunk, policy_head, value_head;
    // Gaussian: 1/σ and z = (a − μ) / σ (action_size × batch). Categorical: log softmax(logits)
    // and softmax(logits) (choices × batch), and the chosen index of each sample.
    Eigen::VectorXf inverse_std;
    Eigen::MatrixXf standardized_actions, log_probabilities, probabilities;
    std::vector<int64_t> choices;
    Eigen::RowVectorXf log_prob, entropy, value;  // log π(a|s), H[π(·|s)], V(s) per sample

    // ∂L/∂(policy head output), ∂L/∂(trunk outputs).
    Eigen::MatrixXf head_gradient, policy_latent_gradient, value_latent_gradient;
  };

  // Locates every parameter of `policy` in `flat`, whose buffers it views; raises Error if one
  // is not a view of it or a layer's weight and bias are not adjacent.
  DenseActorCritic(const ActorCriticImpl& policy, const FlatParameters& flat);

  // log π(a|s), H[π(·|s)] and V(s) for each column, into `tape`. `parameters` is the whole
  // flat buffer.
  void evaluate(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                const Eigen::Ref<const Eigen::MatrixXf>& observations,
                const Eigen::Ref<const Eigen::MatrixXf>& actions, Tape& tape) const;

  // Adds to `parameter_gradient` (the whole flat gradient buffer) the gradient of a loss L
  // whose derivatives with respect to each sample's log π, H and V are given (1 × batch each),
  // for the pass recorded in `tape`.
  void backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;

  int64_t parameter_count() const { return parameter_count_; }

 private:
  // A network and where its parameters start in the flat buffer.
  struct Placed {
    DenseMlp mlp;
    int64_t offset = 0;
  };

  // log π(a|s) and H from the policy head's output (μ or logits) in tape.policy_head.
  void distribution_forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                            const Eigen::Ref<const Eigen::MatrixXf>& actions, Tape& tape) const;
  // ∂L/∂(head output) into tape.head_gradient; a Gaussian's ∂L/∂log σ added to
  // `parameter_gradient` directly.
  void distribution_backward(const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                             const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                             Tape& tape, Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;

  bool discrete_ = false;
  bool shared_trunk_ = false;
  std::optional<Placed> policy_trunk_, value_trunk_;  // none: the head reads the observation
  Placed policy_head_, value_head_;
  int64_t log_std_offset_ = -1;
  int64_t action_size_ = 0;
  int64_t parameter_count_ = 0;
};

}  // namespace tendril::nn
