#pragma once

#include <memory>
#include <vector>

#include "tendril/nn/dense_mlp.hpp"
#include "tendril/nn/feature_head.hpp"
#include "tendril/nn/feature_heads.hpp"

namespace tendril::nn {

// Seed 001's "MLP Head" (thesis §5.1.2, Fig. 5.2, 2): the flattened history through an MLP with
// ReLU hidden layers and a linear output (the author's code: 600 → 1024 → 1024 → 512), by hand
// on nn::DenseMlp.
class MlpHead : public FeatureHead {
 public:
  static constexpr const char* kKind = "mlp";

  explicit MlpHead(DenseMlp network);

  std::string kind() const override { return kKind; }
  int64_t input_size() const override { return network_.input_size(); }
  int64_t output_size() const override { return network_.output_size(); }
  int64_t parameter_count() const override { return network_.parameter_count(); }
  const DenseMlp& network() const { return network_; }

  std::unique_ptr<Tape> make_tape() const override;
  void forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
               const Eigen::Ref<const Eigen::MatrixXf>& inputs, bool record,
               Tape& tape) const override;
  void backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                Eigen::Ref<Eigen::VectorXf> parameter_gradient) const override;
  void write(ArchiveWriter& writer, const std::string& prefix) const override;

  // `spec.inputs` → spec.layers with ReLU, weights as LibTorch's nn.Linear default from `rng`.
  static CreatedHead create(const FeatureHeadSpec& spec, Rng& rng);
  static std::shared_ptr<const FeatureHead> read(const ArchiveReader& reader,
                                                 const std::string& prefix);

 private:
  DenseMlp network_;
};

}  // namespace tendril::nn
