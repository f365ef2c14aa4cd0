#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/core/space.hpp"
#include "tendril/nn/activation.hpp"

namespace tendril::nn {

// The architecture of an actor-critic: what a policy network is, independent of LibTorch, so
// that the training module and its Eigen inference copy are built from the same description.
// Defaults are Stable-Baselines3's MlpPolicy for on-policy algorithms: separate 64×64 tanh
// trunks for policy and value, orthogonal initialisation, log σ initialised to 0.
struct ActorCriticSpec {
  int64_t observation_size = 0;
  bool discrete = false;    // categorical over `action_size` choices, else diagonal Gaussian
  int64_t action_size = 0;  // Gaussian: action dimensions; categorical: number of choices
  std::vector<int64_t> policy_layers{64, 64};
  std::vector<int64_t> value_layers{64, 64};
  // One trunk (policy_layers) feeding both heads, instead of one trunk each.
  bool shared_trunk = false;
  Activation activation = Activation::kTanh;
  // A squashing activation on the Gaussian mean (the policy head's output): none by default, as
  // SB3; seed 002's actor has softsign "at input, hidden and output layers" (§IV-A3).
  std::optional<Activation> policy_output_activation;
  bool orthogonal_init = true;
  double log_std_init = 0.0;

  // Sets the sizes for these spaces (Box → Gaussian, Discrete → categorical); the
  // architecture fields are kept. Observations must be a Box.
  ActorCriticSpec with_spaces(const Space& observation_space, const Space& action_space) const;

  // Reads the architecture from the `policy` mapping of an algorithm config over `fallback`:
  //   net_arch: [64, 64]        layers of both trunks (or of the shared trunk)
  //   pi_layers, vf_layers      per-trunk layers, overriding net_arch
  //   shared_trunk: false, activation: tanh|relu|softsign, ortho_init: true, log_std_init: 0.0
  //   pi_output_activation: none|tanh|relu|softsign (the Gaussian mean's; none by default)
  // Unknown keys are rejected by the caller's reject_unknown().
  static ActorCriticSpec from_config(const Config& policy, const ActorCriticSpec& fallback);
  static ActorCriticSpec from_config(const Config& policy);  // over the defaults
};

}  // namespace tendril::nn
