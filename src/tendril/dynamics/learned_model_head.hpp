#pragma once

#include <torch/torch.h>

#include <memory>
#include <vector>

#include "tendril/dynamics/model.hpp"
#include "tendril/nn/feature_head.hpp"
#include "tendril/nn/feature_heads.hpp"

namespace tendril::dynamics {

// A policy head made of a learned dynamics model of seed 001 (thesis §5.1.2, Fig. 5.2):
//   lk_encoder — the model's recurrent encoder over the window ("LK Head (Encoder)"): its last
//                layer's output at the newest row, hidden_size features;
//   lk_full    — the whole model ("LK Head (Full)"): the predicted change of state Δx̂
//                (state_dim features).
// It reads a window of window_length rows [θx, θy, θ̇x, θ̇y, u_x, u_y] (oldest first, as
// SmaLimb/LearnedReach-v0's history) and normalises them with the model's normaliser, as the
// model does. The weights of its part of the network are the caller's flat vector (the layout
// of the part's parameters in LibTorch's order); a pass binds the network's parameters to that
// memory and runs LibTorch, whose autograd gives the backward pass. Between a recorded forward
// pass and its backward pass the head must not run with other weights.
class LearnedModelHead : public nn::FeatureHead {
 public:
  enum class Part { kEncoder, kFull };
  static constexpr const char* kEncoderKind = "lk_encoder";
  static constexpr const char* kFullKind = "lk_full";

  // Raises Error for a model without a recurrent encoder (kEncoder of a softsign LSTM).
  LearnedModelHead(ModelDescription description, Part part);

  std::string kind() const override { return part_ == Part::kEncoder ? kEncoderKind : kFullKind; }
  int64_t input_size() const override;
  int64_t output_size() const override;
  int64_t parameter_count() const override { return parameter_count_; }
  const ModelDescription& description() const { return description_; }

  // The weights of this head's part of `network` (a network of the same description), flat.
  Eigen::VectorXf weights_of(SequenceNetwork& network) const;

  std::unique_ptr<Tape> make_tape() const override;
  void forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
               const Eigen::Ref<const Eigen::MatrixXf>& inputs, bool record,
               Tape& tape) const override;
  void backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                Eigen::Ref<Eigen::VectorXf> parameter_gradient) const override;
  void write(ArchiveWriter& writer, const std::string& prefix) const override;

 private:
  // The part's parameters in `network`, in LibTorch's order.
  std::vector<torch::Tensor> part_parameters(SequenceNetwork& network) const;
  // Points the network's parameters at `parameters`.
  void bind(const Eigen::Ref<const Eigen::VectorXf>& parameters) const;
  torch::Tensor run(const torch::Tensor& windows) const;

  ModelDescription description_;
  Part part_;
  std::shared_ptr<SequenceNetwork> network_;
  std::shared_ptr<torch::nn::Module> encoder_;  // the recurrent stack that reads the window
  std::vector<torch::Tensor> parameters_;       // of the part, bound to the caller's weights
  int64_t parameter_count_ = 0;
  torch::Tensor row_offset_, row_scale_;
  mutable const float* bound_to_ = nullptr;
};

}  // namespace tendril::dynamics
