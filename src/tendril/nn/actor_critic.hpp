#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/nn/actor_critic_spec.hpp"
#include "tendril/nn/dense_mlp.hpp"

namespace tendril::nn {

// The policy and value networks of an on-policy actor-critic (SB3's ActorCriticPolicy) over
// one flat float parameter vector that the caller owns, with their passes and derivatives
// written out by hand:
//   policy trunk → policy head (mean or logits) [+ state-independent log σ]
//   value trunk  → value head (scalar)
// With `spec.shared_trunk` one trunk feeds both heads. An empty layer list means the head reads
// the observation. The policy's parameters come first and the value's after them, each block
// contiguous: [policy trunk | policy head | log σ | value trunk | value head], so an optimizer
// or a trust-region step can work on either block alone. A shared trunk belongs to the policy.
//
// Batches are matrices with one column per sample: observations (observation_size × batch),
// actions (action_size × batch for a Gaussian; 1 × batch of choice indices, categorical).
class ActorCritic {
 public:
  // A forward pass and what its backward pass needs; reusing one for batches of the same size
  // does not allocate.
  struct Tape {
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
    // ∂L/∂(policy head output), ∂L/∂(trunk outputs); head tangent (Fisher products).
    Eigen::MatrixXf head_gradient, policy_latent_gradient, value_latent_gradient, head_tangent;
  };

  ActorCritic() = default;
  // Raises Error on non-positive sizes.
  explicit ActorCritic(const ActorCriticSpec& spec);

  const ActorCriticSpec& spec() const { return spec_; }
  int64_t parameter_count() const { return parameter_count_; }
  int64_t policy_parameter_count() const { return policy_parameter_count_; }
  // Gaussian actions have action_size components; a categorical action is one index.
  int64_t action_dims() const { return spec_.discrete ? 1 : spec_.action_size; }

  // SB3's initialisation: orthogonal weights (gain √2 in the trunks, 0.01 for the policy head,
  // 1 for the value head) and zero biases when `spec.orthogonal_init`, else LibTorch's default
  // uniform ±1/√fan_in; log σ = spec.log_std_init. Layers in order policy trunk, value trunk,
  // policy head, value head, each drawn from `rng`.
  void initialize(Eigen::Ref<Eigen::VectorXf> parameters, Rng& rng) const;

  // Acting: actions (action_dims × batch; Gaussian samples unclipped, indices as floats) and
  // their log π; `deterministic` takes the mode. Random draws come from `rng`.
  void act(const Eigen::Ref<const Eigen::VectorXf>& parameters,
           const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic, Rng& rng,
           Eigen::MatrixXf& actions, Eigen::VectorXf& log_probs, Tape& tape) const;
  // V(s) per column.
  void value(const Eigen::Ref<const Eigen::VectorXf>& parameters,
             const Eigen::Ref<const Eigen::MatrixXf>& observations, Eigen::VectorXf& values,
             Tape& tape) const;

  // log π(a|s), H[π(·|s)] and V(s) for each column, into `tape`.
  void evaluate(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                const Eigen::Ref<const Eigen::MatrixXf>& observations,
                const Eigen::Ref<const Eigen::MatrixXf>& actions, Tape& tape) const;
  // The same without the value network (a trust-region step on the policy alone).
  void evaluate_policy(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                       const Eigen::Ref<const Eigen::MatrixXf>& observations,
                       const Eigen::Ref<const Eigen::MatrixXf>& actions, Tape& tape) const;

  // Adds to `parameter_gradient` the gradient of a loss L whose derivatives with respect to
  // each sample's log π, H and V are given (1 × batch each), for the pass in `tape`.
  void backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;
  // The policy part alone (after evaluate_policy): entropy and log π derivatives.
  void backward_policy(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                       const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                       const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                       Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;

  // The value part alone (after value()): adds ∂L/∂(value parameters) for ∂L/∂V given per
  // sample. With a shared trunk only the value head receives it (the trunk is the policy's).
  void backward_value(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                      const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                      Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;

  // The distribution of the pass in `tape` (after evaluate or evaluate_policy): head outputs
  // (μ or logits) and, for a Gaussian, log σ.
  struct Distribution {
    Eigen::MatrixXf head;  // μ (action_size × batch) or logits (choices × batch)
    Eigen::VectorXf log_std;
  };
  Distribution distribution(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                            const Tape& tape) const;
  // Mean over samples of KL(old ‖ new).
  double mean_kl(const Distribution& old_distribution, const Distribution& new_distribution) const;

  // The Fisher-vector product of the policy at the pass in `tape` (evaluated with `parameters`
  // = θ_old): F v = (1/N) Σ_i J_iᵀ M_i J_i v, with J_i the Jacobian of sample i's distribution
  // parameters and M_i the Fisher information of the distribution in them — the Hessian of
  // the mean KL(π_old ‖ π_θ) at θ_old. `tangent` and `product` span the policy block.
  void fisher_vector_product(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                             const Eigen::Ref<const Eigen::VectorXf>& tangent,
                             Eigen::Ref<Eigen::VectorXf> product) const;

  // Where log σ lies in the parameter vector (Gaussian only).
  int64_t log_std_offset() const { return log_std_offset_; }

 private:
  struct Placed {  // a network and where its parameters start in the flat vector
    DenseMlp mlp;
    int64_t offset = 0;
  };
  Eigen::Ref<const Eigen::MatrixXf> policy_latent(
      const Eigen::Ref<const Eigen::VectorXf>& parameters,
      const Eigen::Ref<const Eigen::MatrixXf>& observations, Tape& tape) const;
  void run_value(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                 const Eigen::Ref<const Eigen::MatrixXf>& observations,
                 const Eigen::Ref<const Eigen::MatrixXf>& policy_latent, Tape& tape) const;
  void distribution_forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                            const Eigen::Ref<const Eigen::MatrixXf>& actions, Tape& tape) const;
  void distribution_backward(const Eigen::Ref<const Eigen::RowVectorXf>& log_prob_gradient,
                             const Eigen::Ref<const Eigen::RowVectorXf>& entropy_gradient,
                             Tape& tape, Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;
  // Back-propagates tape.head_gradient through the policy head and trunk (the shared trunk
  // also receives tape.value_latent_gradient when `with_value`).
  // The value head's and value trunk's backward pass; `needs_latent_gradient`: keep the head's
  // input gradient in tape.value_latent_gradient (for a value trunk or a shared trunk).
  void value_backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                      const Eigen::Ref<const Eigen::RowVectorXf>& value_gradient,
                      bool needs_latent_gradient,
                      Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;
  void policy_backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                       bool with_value, Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;

  ActorCriticSpec spec_;
  std::optional<Placed> policy_trunk_, value_trunk_;  // none: the head reads the observation
  Placed policy_head_, value_head_;
  int64_t log_std_offset_ = -1;
  int64_t policy_parameter_count_ = 0;
  int64_t parameter_count_ = 0;
};

}  // namespace tendril::nn
