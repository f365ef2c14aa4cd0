#include "tendril/nn/mlp_head.hpp"

#include "tendril/core/error.hpp"
#include "tendril/nn/mlp_archive.hpp"

namespace tendril::nn {

namespace {

struct MlpTape : FeatureHead::Tape {
  DenseMlp::Tape pass;
  std::vector<Eigen::MatrixXf> scratch;
};

}  // namespace

MlpHead::MlpHead(DenseMlp network) : network_(std::move(network)) {
  require(!network_.tanh_output() && !network_.activates_output(),
          "an MLP head has a linear output layer", "nn::MlpHead");
}

std::unique_ptr<FeatureHead::Tape> MlpHead::make_tape() const {
  return std::make_unique<MlpTape>();
}

void MlpHead::forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                      const Eigen::Ref<const Eigen::MatrixXf>& inputs, bool, Tape& tape) const {
  auto& own = dynamic_cast<MlpTape&>(tape);
  network_.forward(parameters, inputs, own.pass);
  own.output = own.pass.output();
}

void MlpHead::backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                       const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                       Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  auto& own = dynamic_cast<MlpTape&>(tape);
  network_.backward(parameters, own.pass, output_gradient, parameter_gradient, nullptr,
                    own.scratch);
}

void MlpHead::write(ArchiveWriter& writer, const std::string& prefix) const {
  write_dense_mlp(writer, prefix + "_network", network_);
}

CreatedHead MlpHead::create(const FeatureHeadSpec& spec, Rng& rng) {
  std::vector<int64_t> sizes{spec.inputs};
  sizes.insert(sizes.end(), spec.layers.begin(), spec.layers.end());
  auto head = std::make_shared<MlpHead>(DenseMlp(sizes, Activation::kRelu));
  Eigen::VectorXf parameters(head->parameter_count());
  head->network().initialize(parameters, rng);
  return {std::move(head), std::move(parameters)};
}

std::shared_ptr<const FeatureHead> MlpHead::read(const ArchiveReader& reader,
                                                 const std::string& prefix) {
  return std::make_shared<MlpHead>(read_dense_mlp(reader, prefix + "_network"));
}

}  // namespace tendril::nn
