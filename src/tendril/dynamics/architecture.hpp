#pragma once

#include <cstdint>
#include <string>

#include "tendril/core/config.hpp"

namespace tendril::dynamics {

// The learned dynamics networks of seeds 001 and 002.
enum class Architecture {
  // Seed 001 (thesis §4.2.4, Fig. 4.3): a window of n rows [x, u] → Δx = tanh(·) · bound.
  kRnn,               // vanilla (tanh) RNN, L layers, linear head on the last step
  kLstm,              // LSTM, L layers, linear head on the last step
  kSeq2Seq,           // LSTM encoder over the window; LSTM decoder, started from the encoder's
                      // final state, reads the newest row for one step
  kSeq2SeqAttention,  // as kSeq2Seq, the decoder's input replaced by multi-head dot-product
                      // attention of the projected newest row over the encoder outputs
  // Seed 002 (§III-C, eq. (1)): (x_t, x_{t−1}, τ_t, τ_{t−1}, τ_{t−2}) normalised to [−1, 1] as
  // one time step of one LSTM layer with softsign activations, dropout, a dense softsign output
  // → x_{t+1} normalised.
  kSoftsignLstm,
};

std::string architecture_name(Architecture kind);
// The architecture called `name`; raises Error naming `where` for an unknown name.
Architecture parse_architecture(const std::string& name, const std::string& where);

enum class Normalization {
  kStandard,  // (v − mean) / std of the training rows
  kMinMax,    // onto [−1, 1] by the training rows' minimum and maximum
  kNone,
};

std::string normalization_name(Normalization kind);
Normalization parse_normalization(const std::string& name, const std::string& where);

// Everything that fixes a network's shape and meaning; stored in the model file.
//
//   model:
//     architecture: seq2seq_attention   # rnn | lstm | seq2seq | seq2seq_attention | softsign_lstm
//     hidden_size: 512
//     layers: 3                 # recurrent layers (encoder and decoder each, for seq2seq)
//     heads: 4                  # attention heads (seq2seq_attention)
//     window: 100               # rows of history, n (softsign_lstm: 3)
//     output_bound: 100         # Δx = bound · tanh(·), seed 001's "domain boundary"
//     dropout: 0.0              # softsign_lstm: after the LSTM layer (seed 002: 0.3)
//     normalization: standard   # standard | minmax | none (softsign_lstm default: minmax)
struct ArchitectureSpec {
  static constexpr int kMaxColumns = 1024;
  static constexpr int kMaxHiddenSize = 8192;
  static constexpr int kMaxLayers = 32;
  static constexpr int kMaxWindow = 100000;
  // Δx per step in normalised units: far above any robot's, low enough that bound · tanh(·)
  // and its denormalisation stay finite in float32.
  static constexpr double kMaxOutputBound = 1e6;

  Architecture kind = Architecture::kLstm;
  int state_dim = 4;
  int input_dim = 2;
  int hidden_size = 64;
  int layers = 2;
  int heads = 4;
  int window = 100;
  double output_bound = 100.0;
  double dropout = 0.0;
  Normalization normalization = Normalization::kStandard;

  // Reads the `model:` mapping; state and input sizes come from the data.
  static ArchitectureSpec from_config(const Config& model, int state_dim, int input_dim);
  // Raises Error naming the offending field (a size out of its range above among them).
  void validate() const;

  // Seed 001's networks predict the change Δx in the data's units (thesis eq. 4.3); seed 002's
  // the next state in normalised units.
  bool predicts_change() const { return kind != Architecture::kSoftsignLstm; }
  // The network's input: a sequence of `sequence_length()` vectors of `feature_size()` values.
  int feature_size() const;
  int sequence_length() const;
  int row_size() const { return state_dim + input_dim; }

  // The number of trainable parameters, in closed form (PyTorch's layouts: two bias vectors
  // per recurrent layer; the softsign LSTM has one, as Keras').
  int64_t parameter_count() const;
};

}  // namespace tendril::dynamics
