#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>

#include "tendril/core/archive.hpp"

namespace tendril::nn {

// A policy head (seed 001, thesis §5.1.2, Fig. 5.2): a feature extractor that reads a window of
// recent history and hands features to the actor and the critics. Like nn::DenseMlp, a head is
// a shape with passes; its weights are one flat float vector the caller owns, so that Adam,
// Polyak averaging of a target copy and checkpoints are whole-vector operations whatever the
// head is made of. Declared here without LibTorch: the MLP head is nn::MlpHead; the heads made
// of a learned dynamics model are implemented in dynamics/ with LibTorch autograd and reach
// algorithms through install_feature_head_kind (nn/feature_heads.hpp).
//
// Batches are matrices with one column per sample (input_size × batch in, output_size × batch
// out). A head keeps scratch state between its passes: one head must not run two passes from
// two threads at once.
class FeatureHead {
 public:
  // A forward pass and, when it was recorded, what its backward pass needs.
  struct Tape {
    virtual ~Tape() = default;
    Eigen::MatrixXf output;  // output_size × batch
  };

  virtual ~FeatureHead() = default;

  // The name its kind is registered under ("mlp", "lk_encoder", "lk_full").
  virtual std::string kind() const = 0;
  virtual int64_t input_size() const = 0;
  virtual int64_t output_size() const = 0;
  virtual int64_t parameter_count() const = 0;

  // A tape for this head's passes.
  virtual std::unique_ptr<Tape> make_tape() const = 0;
  // The head's output for `inputs` into `tape.output`; with `record`, keeps what `backward`
  // needs.
  virtual void forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                       const Eigen::Ref<const Eigen::MatrixXf>& inputs, bool record,
                       Tape& tape) const = 0;
  // Adds ∂L/∂parameters to `parameter_gradient` for ∂L/∂output (output_size × batch) of the
  // pass recorded in `tape`.
  virtual void backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                        const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                        Eigen::Ref<Eigen::VectorXf> parameter_gradient) const = 0;

  // The head's shape (not its weights) under `prefix`, for policy files; its kind's reader
  // (nn/feature_heads.hpp) rebuilds it.
  virtual void write(ArchiveWriter& writer, const std::string& prefix) const = 0;
};

}  // namespace tendril::nn
