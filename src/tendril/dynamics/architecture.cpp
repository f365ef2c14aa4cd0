#include "tendril/dynamics/architecture.hpp"

#include <cmath>
#include <cstdio>

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

namespace {

std::string key(const Config& config, const std::string& name) {
  return config.source() + ": " + (config.path().empty() ? name : config.path() + "." + name);
}

// Parameters of one PyTorch recurrent layer: `gates` blocks of W_ih, W_hh, b_ih, b_hh.
int64_t recurrent_layer(int64_t gates, int64_t input, int64_t hidden) {
  return gates * hidden * (input + hidden + 2);
}

int64_t recurrent_stack(int64_t gates, int64_t input, int64_t hidden, int64_t layers) {
  return recurrent_layer(gates, input, hidden) +
         (layers - 1) * recurrent_layer(gates, hidden, hidden);
}

int64_t linear(int64_t in, int64_t out) { return in * out + out; }

}  // namespace

Architecture parse_architecture(const std::string& name, const std::string& where) {
  if (name == "rnn") return Architecture::kRnn;
  if (name == "lstm") return Architecture::kLstm;
  if (name == "seq2seq") return Architecture::kSeq2Seq;
  if (name == "seq2seq_attention") return Architecture::kSeq2SeqAttention;
  if (name == "softsign_lstm") return Architecture::kSoftsignLstm;
  throw Error("unknown architecture '" + name +
                  "' (expected rnn, lstm, seq2seq, seq2seq_attention or softsign_lstm)",
              where);
}

Normalization parse_normalization(const std::string& name, const std::string& where) {
  if (name == "standard") return Normalization::kStandard;
  if (name == "minmax") return Normalization::kMinMax;
  if (name == "none") return Normalization::kNone;
  throw Error("unknown normalization '" + name + "' (expected standard, minmax or none)", where);
}

std::string architecture_name(Architecture kind) {
  switch (kind) {
    case Architecture::kRnn:
      return "rnn";
    case Architecture::kLstm:
      return "lstm";
    case Architecture::kSeq2Seq:
      return "seq2seq";
    case Architecture::kSeq2SeqAttention:
      return "seq2seq_attention";
    case Architecture::kSoftsignLstm:
      return "softsign_lstm";
  }
  return "?";
}

std::string normalization_name(Normalization kind) {
  switch (kind) {
    case Normalization::kStandard:
      return "standard";
    case Normalization::kMinMax:
      return "minmax";
    case Normalization::kNone:
      return "none";
  }
  return "?";
}

ArchitectureSpec ArchitectureSpec::from_config(const Config& model, int state_dim, int input_dim) {
  ArchitectureSpec spec;
  spec.kind =
      parse_architecture(model.get<std::string>("architecture"), key(model, "architecture"));
  const bool seed002 = spec.kind == Architecture::kSoftsignLstm;
  spec.state_dim = state_dim;
  spec.input_dim = input_dim;
  spec.hidden_size = model.get_or<int>("hidden_size", seed002 ? 128 : 64);
  spec.layers = model.get_or<int>("layers", seed002 ? 1 : 2);
  spec.heads = model.get_or<int>("heads", 4);
  spec.window = model.get_or<int>("window", seed002 ? 3 : 100);
  spec.output_bound = model.get_or<double>("output_bound", 100.0);
  spec.dropout = model.get_or<double>("dropout", seed002 ? 0.3 : 0.0);
  spec.normalization = parse_normalization(
      model.get_or<std::string>("normalization", seed002 ? "minmax" : "standard"),
      key(model, "normalization"));
  try {
    spec.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), key(model, e.where()));
  }
  return spec;
}

void ArchitectureSpec::validate() const {
  // The upper limits lie far above any robot model (the thesis' largest: 512 × 3, window 100)
  // and keep parameter_count() and every tensor size within 64-bit integers, whatever a file's
  // header claims.
  auto within = [](int value, int low, int high, const std::string& name) {
    require(value >= low && value <= high,
            "must lie in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " +
                std::to_string(value),
            name);
  };
  within(state_dim, 1, kMaxColumns, "state_dim");
  within(input_dim, 0, kMaxColumns, "input_dim");
  within(hidden_size, 1, kMaxHiddenSize, "hidden_size");
  within(layers, 1, kMaxLayers, "layers");
  within(window, 1, kMaxWindow, "window");
  if (!(std::isfinite(output_bound) && output_bound > 0.0 && output_bound <= kMaxOutputBound)) {
    char value[32];
    std::snprintf(value, sizeof value, "%g", output_bound);
    throw Error(std::string("must lie in (0, 1e6], got ") + value, "output_bound");
  }
  require(dropout >= 0.0 && dropout < 1.0, "must lie in [0, 1)", "dropout");
  if (kind == Architecture::kSeq2SeqAttention) {
    require(
        heads >= 1 && hidden_size % heads == 0,
        "must divide hidden_size " + std::to_string(hidden_size) + ", got " + std::to_string(heads),
        "heads");
  }
  if (kind == Architecture::kSoftsignLstm) {
    require(window == 3, "must be 3 for softsign_lstm (x_t, x_{t−1}; τ_t, τ_{t−1}, τ_{t−2})",
            "window");
    require(layers == 1, "must be 1 for softsign_lstm", "layers");
  } else {
    require(dropout == 0.0, "is only used by softsign_lstm", "dropout");
  }
}

int ArchitectureSpec::feature_size() const {
  return kind == Architecture::kSoftsignLstm ? 2 * state_dim + 3 * input_dim : row_size();
}

int ArchitectureSpec::sequence_length() const {
  return kind == Architecture::kSoftsignLstm ? 1 : window;
}

int64_t ArchitectureSpec::parameter_count() const {
  const int64_t f = feature_size();
  const int64_t h = hidden_size;
  const int64_t head = linear(h, state_dim);
  switch (kind) {
    case Architecture::kRnn:
      return recurrent_stack(1, f, h, layers) + head;
    case Architecture::kLstm:
      return recurrent_stack(4, f, h, layers) + head;
    case Architecture::kSeq2Seq:
      return 2 * recurrent_stack(4, f, h, layers) + head;
    case Architecture::kSeq2SeqAttention:
      // Query projection F → H; attention in-projections (3 H × H + 3 H) and output projection
      // (H × H + H); back to the decoder's input size H → F.
      return 2 * recurrent_stack(4, f, h, layers) + linear(f, h) + 4 * h * h + 4 * h +
             linear(h, f) + head;
    case Architecture::kSoftsignLstm:
      return 4 * h * (f + h + 1) + head;
  }
  return 0;
}

}  // namespace tendril::dynamics
