#include "tendril/dynamics/seq2seq_network.hpp"

#include "tendril/dynamics/fused_lstm.hpp"
#include "tendril/dynamics/parameter_init.hpp"

namespace tendril::dynamics {

Seq2SeqNetwork::Seq2SeqNetwork(const ArchitectureSpec& spec) : SequenceNetwork(spec) {
  const auto lstm = torch::nn::LSTMOptions(spec.feature_size(), spec.hidden_size)
                        .num_layers(spec.layers)
                        .batch_first(true);
  encoder_ = register_module("encoder", torch::nn::LSTM(lstm));
  if (spec.kind == Architecture::kSeq2SeqAttention) {
    query_ = register_module("query", torch::nn::Linear(spec.feature_size(), spec.hidden_size));
    attention_ = register_module(
        "attention", torch::nn::MultiheadAttention(
                         torch::nn::MultiheadAttentionOptions(spec.hidden_size, spec.heads)));
    back_ = register_module("back", torch::nn::Linear(spec.hidden_size, spec.feature_size()));
  }
  decoder_ = register_module("decoder", torch::nn::LSTM(lstm));
  head_ = register_module("head", torch::nn::Linear(spec.hidden_size, spec.state_dim));
}

torch::Tensor Seq2SeqNetwork::forward(const torch::Tensor& inputs) {
  const auto [encoded, h_n, c_n] = fused_lstm(encoder_, inputs);
  torch::Tensor step = inputs.narrow(1, inputs.size(1) - 1, 1);  // [B, 1, F]: [x_t, u_t]
  if (attention_) {
    // MultiheadAttention takes [sequence, batch, embedding].
    const torch::Tensor query = query_->forward(step).transpose(0, 1);
    const torch::Tensor memory = encoded.transpose(0, 1);
    const torch::Tensor attended =
        std::get<0>(attention_->forward(query, memory, memory, {}, /*need_weights=*/false));
    step = back_->forward(attended.transpose(0, 1));
  }
  const torch::Tensor decoded = std::get<0>(fused_lstm(decoder_, step, h_n, c_n));
  return torch::tanh(head_->forward(decoded.select(1, 0))) * spec_.output_bound;
}

void Seq2SeqNetwork::initialize(Rng& rng) {
  init_recurrent(*encoder_, spec_.hidden_size, rng);
  if (attention_) {
    init_linear(query_, rng);
    // PyTorch's MultiheadAttention: Xavier-uniform in-projection of shape [3E, E], zero biases,
    // the output projection a default Linear with a zero bias.
    const int64_t embed = spec_.hidden_size;
    fill_glorot_uniform(attention_->in_proj_weight, embed, 3 * embed, rng);
    fill_constant(attention_->in_proj_bias, 0.0);
    init_linear(attention_->out_proj, rng);
    fill_constant(attention_->out_proj->bias, 0.0);
    init_linear(back_, rng);
  }
  init_recurrent(*decoder_, spec_.hidden_size, rng);
  init_linear(head_, rng);
}

}  // namespace tendril::dynamics
