#include "tendril/dynamics/learned_model_head.hpp"

#include <string>

#include "tendril/core/error.hpp"
#include "tendril/dynamics/fused_lstm.hpp"
#include "tendril/dynamics/model_file_format.hpp"

namespace tendril::dynamics {

namespace {

constexpr const char* kWhere = "dynamics::LearnedModelHead";

struct TorchTape : nn::FeatureHead::Tape {
  torch::Tensor result;  // [B, output], with its autograd graph when recorded
  const float* weights = nullptr;
};

torch::Tensor tensor_view(const float* data, const torch::IntArrayRef sizes) {
  return torch::from_blob(const_cast<float*>(data), sizes, torch::kFloat);
}

// The module that reads the window: a Seq2Seq's encoder, or a recurrent network's stack.
std::shared_ptr<torch::nn::Module> recurrent_stack(SequenceNetwork& network) {
  for (const auto& child : network.named_children()) {
    if (child.key() == "encoder" || child.key() == "lstm" || child.key() == "rnn") {
      return child.value();
    }
  }
  return nullptr;
}

}  // namespace

LearnedModelHead::LearnedModelHead(ModelDescription description, Part part)
    : description_(std::move(description)), part_(part) {
  description_.validate(kWhere);
  network_ = make_network(description_.architecture);
  network_->eval();
  encoder_ = recurrent_stack(*network_);
  require(part_ == Part::kFull || encoder_ != nullptr,
          "a " + architecture_name(description_.architecture.kind) +
              " model has no recurrent encoder to use as a head",
          kWhere);
  require(description_.architecture.kind != Architecture::kSoftsignLstm,
          "seed 002's softsign LSTM reads three rows, not a window; it cannot be a policy head",
          kWhere);
  parameters_ = part_parameters(*network_);
  for (const torch::Tensor& p : parameters_) parameter_count_ += p.numel();
  const Normalizer& n = description_.normalizer;
  row_offset_ = torch::from_blob(const_cast<double*>(n.offset.data()), {n.size()}, torch::kDouble)
                    .to(torch::kFloat);
  row_scale_ = torch::from_blob(const_cast<double*>(n.scale.data()), {n.size()}, torch::kDouble)
                   .to(torch::kFloat);
}

int64_t LearnedModelHead::input_size() const {
  return static_cast<int64_t>(description_.architecture.window) *
         description_.architecture.row_size();
}

int64_t LearnedModelHead::output_size() const {
  return part_ == Part::kEncoder ? description_.architecture.hidden_size
                                 : description_.architecture.state_dim;
}

std::vector<torch::Tensor> LearnedModelHead::part_parameters(SequenceNetwork& network) const {
  if (part_ == Part::kFull) return network.parameters();
  return recurrent_stack(network)->parameters();
}

Eigen::VectorXf LearnedModelHead::weights_of(SequenceNetwork& network) const {
  Eigen::VectorXf weights(parameter_count_);
  int64_t offset = 0;
  for (const torch::Tensor& p : part_parameters(network)) {
    const torch::Tensor values = p.detach().contiguous();
    require(offset + values.numel() <= parameter_count_, "the network is not this head's shape",
            kWhere);
    std::copy_n(values.data_ptr<float>(), values.numel(), weights.data() + offset);
    offset += values.numel();
  }
  require(offset == parameter_count_, "the network is not this head's shape", kWhere);
  return weights;
}

void LearnedModelHead::bind(const Eigen::Ref<const Eigen::VectorXf>& parameters) const {
  require(parameters.size() == parameter_count_,
          "weights have " + std::to_string(parameters.size()) + " values, the head " +
              std::to_string(parameter_count_),
          kWhere);
  if (bound_to_ == parameters.data()) return;
  int64_t offset = 0;
  for (const torch::Tensor& p : parameters_) {
    p.set_data(tensor_view(parameters.data() + offset, p.sizes()));
    offset += p.numel();
  }
  bound_to_ = parameters.data();
}

torch::Tensor LearnedModelHead::run(const torch::Tensor& windows) const {
  const torch::Tensor rows = (windows - row_offset_) / row_scale_;
  if (part_ == Part::kFull) return network_->forward(rows);
  torch::Tensor outputs;
  if (auto lstm = std::dynamic_pointer_cast<torch::nn::LSTMImpl>(encoder_)) {
    outputs = std::get<0>(fused_lstm(torch::nn::LSTM(lstm), rows));
  } else {
    outputs = std::get<0>(std::dynamic_pointer_cast<torch::nn::RNNImpl>(encoder_)->forward(rows));
  }
  return outputs.select(1, outputs.size(1) - 1);
}

std::unique_ptr<nn::FeatureHead::Tape> LearnedModelHead::make_tape() const {
  return std::make_unique<TorchTape>();
}

void LearnedModelHead::forward(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                               const Eigen::Ref<const Eigen::MatrixXf>& inputs, bool record,
                               Tape& tape) const {
  require(inputs.rows() == input_size(),
          "inputs have " + std::to_string(inputs.rows()) + " values, the head reads " +
              std::to_string(input_size()),
          kWhere);
  auto& own = dynamic_cast<TorchTape&>(tape);
  bind(parameters);
  const ArchitectureSpec& a = description_.architecture;
  const int64_t batch = inputs.cols();
  // Column i is env i's window, row after row: a [B, window, row] tensor with a column stride.
  const torch::Tensor windows =
      torch::from_blob(const_cast<float*>(inputs.data()), {batch, a.window, a.row_size()},
                       {inputs.outerStride(), a.row_size(), 1}, torch::kFloat);
  torch::Tensor result;
  if (record) {
    result = run(windows);
  } else {
    torch::NoGradGuard no_grad;
    result = run(windows);
  }
  own.result = record ? result : torch::Tensor();
  own.weights = record ? parameters.data() : nullptr;
  const torch::Tensor values = result.detach().contiguous();
  own.output.resize(output_size(), batch);
  std::copy_n(values.data_ptr<float>(), values.numel(), own.output.data());
}

void LearnedModelHead::backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Tape& tape,
                                const Eigen::Ref<const Eigen::MatrixXf>& output_gradient,
                                Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  auto& own = dynamic_cast<TorchTape&>(tape);
  require(own.result.defined(), "backward of a pass that was not recorded", kWhere);
  require(own.weights == parameters.data() && bound_to_ == parameters.data(),
          "the head ran with other weights between its forward and backward passes", kWhere);
  require(output_gradient.rows() == output_size() && output_gradient.cols() == own.result.size(0),
          "the gradient does not match the forward pass", kWhere);
  const torch::Tensor gradient = torch::from_blob(
      const_cast<float*>(output_gradient.data()), {output_gradient.cols(), output_gradient.rows()},
      {output_gradient.outerStride(), 1}, torch::kFloat);
  torch::autograd::backward({own.result}, {gradient});
  own.result = torch::Tensor();  // the graph is spent
  int64_t offset = 0;
  for (const torch::Tensor& p : parameters_) {
    if (p.grad().defined()) {
      const torch::Tensor g = p.grad().contiguous();
      parameter_gradient.segment(offset, p.numel()) +=
          Eigen::Map<const Eigen::VectorXf>(g.data_ptr<float>(), p.numel());
      p.mutable_grad().reset();
    }
    offset += p.numel();
  }
}

void LearnedModelHead::write(ArchiveWriter& writer, const std::string& prefix) const {
  writer.put(prefix + "_model", description_yaml(description_));
}

}  // namespace tendril::dynamics
