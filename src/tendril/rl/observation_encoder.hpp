#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>

#include "tendril/nn/feature_head.hpp"
#include "tendril/nn/layer_norm.hpp"

namespace tendril::rl {

// How actor and critics read an observation through a policy head (seed 001, thesis §5.1.2,
// "Input parsing", Fig. 5.2): the observation is [direct | history], the history being the last
// head.input_size() values (SmaLimb/LearnedReach-v0 with `history`: 100 rows of state and
// previous throttles); the head reads the history, its output is layer-normalised, and the
// networks read
//   encoded = [LayerNorm(head(history)); direct]
// — the direct part (latest state, previous throttles, goal, power proxy) passed through. Without
// a head the encoded observation is the observation itself.
class ObservationEncoder {
 public:
  // A pass over a batch and what its backward pass needs.
  struct Pass {
    std::unique_ptr<nn::FeatureHead::Tape> head;
    nn::LayerNorm::Tape norm;
    Eigen::MatrixXf encoded;  // encoded_size × batch
    Eigen::MatrixXf norm_gradient;
  };

  ObservationEncoder() = default;
  // `head` may be null (no head). Raises Error if the head reads more values than an
  // observation has.
  ObservationEncoder(std::shared_ptr<const nn::FeatureHead> head, int64_t observation_size);

  bool has_head() const { return head_ != nullptr; }
  const nn::FeatureHead& head() const { return *head_; }
  const std::shared_ptr<const nn::FeatureHead>& shared_head() const { return head_; }
  int64_t observation_size() const { return observation_size_; }
  int64_t direct_size() const { return observation_size_ - (head_ ? head_->input_size() : 0); }
  int64_t feature_size() const { return head_ ? head_->output_size() : 0; }
  int64_t encoded_size() const { return feature_size() + direct_size(); }

  // Encodes `observations` (observation_size × batch) with the head's `parameters` into
  // `pass.encoded`; with `record`, keeps what `backward` needs.
  void encode(const Eigen::Ref<const Eigen::VectorXf>& parameters,
              const Eigen::Ref<const Eigen::MatrixXf>& observations, bool record, Pass& pass) const;
  // Adds to `parameter_gradient` the head's share of ∂L/∂encoded (encoded_size × batch; only
  // its first feature_size() rows reach the head) for the recorded pass.
  void backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Pass& pass,
                const Eigen::Ref<const Eigen::MatrixXf>& encoded_gradient,
                Eigen::Ref<Eigen::VectorXf> parameter_gradient) const;

 private:
  std::shared_ptr<const nn::FeatureHead> head_;
  int64_t observation_size_ = 0;
  nn::LayerNorm norm_;
};

}  // namespace tendril::rl
