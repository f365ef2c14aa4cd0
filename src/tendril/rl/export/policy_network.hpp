#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tendril/nn/activation.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

// A trained policy's deterministic action as a plain feed-forward computation, for export to
// other runtimes (a C header for a microcontroller, ONNX): what Policy::act(…, deterministic =
// true) computes, written out as
//
//   x = clip((observation − mean) · scale, ±clip)        observation normalization, if any
//   x = activation_k(W_k x + b_k)                         for each layer k
//   action = output map of x                              the policy kind's squash and scaling
//
// with scale = 1/sqrt(var + ε) of the normalization the policy was trained behind. The output
// maps:
//   kClip      — clip x to the Box's bounds (PPO/TRPO: the Gaussian's mean, clipped as SB3
//                clips before stepping)
//   kScale     — low + (clip(x, ±1) + 1)·(high − low)/2 (SB3's unscale_action): TD3/DDPG's
//                tanh actor, and SAC's squashed mean, whose tanh becomes the last layer's
//   kClampTanhScale — kScale of tanh(clip(x, ±2)) (SAC with gSDE: SB3's clip_mean)
//   kArgmax    — the index of the largest x, the first on ties (DQN's greedy action, a
//                categorical PPO policy's mode), as a float
// Only the rows of the last layer that the action reads are kept (SAC's log σ rows are not).
struct PolicyNetwork {
  enum class Output { kClip, kScale, kClampTanhScale, kArgmax };
  // Activation after a layer; kNone for a linear layer.
  enum class Activation { kNone, kTanh, kRelu, kSoftsign };

  struct Layer {
    int64_t inputs = 0, outputs = 0;
    std::vector<float> weight;  // outputs × inputs, row-major
    std::vector<float> bias;    // outputs
    Activation activation = Activation::kNone;
  };

  std::string kind;  // the policy's kind() ("actor_critic", …)
  int64_t observation_size = 0;
  // Normalization: empty `mean` when the policy has none.
  std::vector<float> mean, scale;
  float clip = 0.0f;
  std::vector<Layer> layers;
  Output output = Output::kClip;
  // Box actions: their bounds (every output but kArgmax), action_size of each.
  std::vector<float> low, high;
  int64_t action_size = 0;     // components of the action (1 for kArgmax)
  int64_t action_choices = 0;  // kArgmax: the number of discrete actions

  int64_t parameter_count() const;  // weights and biases of every layer
};

// The computation of `policy`'s deterministic action. Raises Error (naming the policy kind) for
// what is not a plain MLP policy: a SAC actor with a history head (its encoder reads a
// LayerNorm'd feature head) and unknown kinds.
PolicyNetwork policy_network(const Policy& policy);

// `network` evaluated in float for one observation, step by step as written above: the
// reference the exports are checked against (it equals Policy::act up to float rounding).
Action evaluate_policy_network(const PolicyNetwork& network, const Observation& observation);

std::string output_name(PolicyNetwork::Output output);
std::string activation_name(PolicyNetwork::Activation activation);

}  // namespace tendril::rl
