#pragma once

#include <Eigen/Core>
#include <memory>

#include "tendril/nn/dense_mlp.hpp"
#include "tendril/nn/feature_head.hpp"
#include "tendril/rl/observation_encoder.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/sac/squashed_gaussian.hpp"
#include "tendril/rl/sac/state_dependent_noise.hpp"

namespace tendril::rl {

// SAC's actor (SB3's SAC Actor): a tanh-squashed diagonal Gaussian, a = tanh(μ + σ ε), whose
// μ and log σ are the two halves of one MLP's output — or, with gSDE, μ from the MLP and the
// noise state-dependent (StateDependentNoiseSample) with a learned latent × action log σ
// stored after the network's weights. Actions in [−1, 1] map affinely onto the Box's bounds.
// The mode is tanh(μ) (gSDE: μ clipped to ±2 first). Not deterministic, it samples; with gSDE
// each call draws a fresh exploration matrix from the given stream. The parameters are the
// trained ones.
//
// With a policy head (seed 001, thesis §5.1.2) the network reads the encoded observation
// [LayerNorm(head(history)); direct] (rl::ObservationEncoder) instead of the observation; the
// head and its weights are part of the policy and of its model file.
class SquashedGaussianPolicy : public Policy {
 public:
  // One reparameterised draw per column and the actor pass behind it.
  struct Sample {
    nn::DenseMlp::Tape tape;
    SquashedGaussianSample gaussian;
    StateDependentNoiseSample sde;
  };

  // `head` may be null (the network reads the observation).
  SquashedGaussianPolicy(const Space& observation_space, const Space& action_space,
                         const std::vector<int64_t>& hidden, nn::Activation activation,
                         bool use_sde, std::shared_ptr<const nn::FeatureHead> head = nullptr);

  std::string kind() const override { return "squashed_gaussian"; }
  const nn::DenseMlp& network() const { return network_; }
  bool uses_sde() const { return use_sde_; }
  int64_t latent_size() const { return latent_size_; }
  // The network's weights, then (gSDE) log σ, latent × action column-major.
  Eigen::VectorXf& parameters() { return parameters_; }
  const Eigen::VectorXf& parameters() const { return parameters_; }
  Eigen::Map<const Eigen::MatrixXf> log_std() const;
  // The head's reading of observations, and the head's weights (empty without a head).
  const ObservationEncoder& encoder() const { return encoder_; }
  Eigen::VectorXf& head_parameters() { return head_parameters_; }
  const Eigen::VectorXf& head_parameters() const { return head_parameters_; }

  // Draws a = tanh(μ + σ ε) for each column of `inputs` — encoded observations
  // (encoder().encode; the observations themselves without a head) — with ε from `rng`, or with
  // gSDE uses `exploration` as the matrix E.
  void sample(const Eigen::Ref<const Eigen::MatrixXf>& inputs, Rng& rng,
              const Eigen::MatrixXf& exploration, Sample& sample) const;
  const Eigen::MatrixXf& actions_of(const Sample& sample) const {
    return use_sde_ ? sample.sde.actions : sample.gaussian.actions;
  }
  const Eigen::VectorXf& log_probs_of(const Sample& sample) const {
    return use_sde_ ? sample.sde.log_probs : sample.gaussian.log_probs;
  }
  // gSDE: the latent features z (last hidden layer, or the observation) of an actor pass.
  const Eigen::MatrixXf& latent_of(const nn::DenseMlp::Tape& tape) const;
  // E ~ N(0, 1), latent × action, drawn column by column from `rng`.
  Eigen::MatrixXf standard_normal_matrix(Rng& rng) const;

  static std::unique_ptr<Policy> read(const ArchiveReader& reader, const Space& observation_space,
                                      const Space& action_space);

 protected:
  void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool deterministic,
                   Rng& rng, Eigen::MatrixXf& actions) const override;
  void write(ArchiveWriter& writer) const override;

 private:
  SquashedGaussianPolicy(const Space& observation_space, const Space& action_space,
                         nn::DenseMlp network, bool use_sde,
                         std::shared_ptr<const nn::FeatureHead> head);

  ObservationEncoder encoder_;
  Eigen::VectorXf head_parameters_;
  mutable ObservationEncoder::Pass pass_;
  nn::DenseMlp network_;  // encoded observation → hidden → [μ; log σ], or μ with gSDE
  bool use_sde_;
  int64_t latent_size_;
  Eigen::VectorXf parameters_;
  mutable Sample sample_;
  Eigen::MatrixXf no_exploration_;
};

}  // namespace tendril::rl
