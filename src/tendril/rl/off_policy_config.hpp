#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/nn/activation.hpp"
#include "tendril/rl/schedule.hpp"

namespace tendril::rl {

// What every off-policy algorithm (SAC, TD3, DDPG, DQN) shares: the replay buffer, when and how
// often to update, the networks' shape. Defaults are Stable-Baselines3's SAC
// (stable_baselines3/sac/sac.py); each algorithm's presets override them.
struct OffPolicyConfig {
  int64_t buffer_size = 1'000'000;  // transitions kept
  int64_t learning_starts = 100;    // uniformly random actions, no updates, before this many steps
  int64_t batch_size = 256;         // transitions per gradient step
  double tau = 0.005;               // Polyak coefficient of the target networks
  double gamma = 0.99;              // discount γ
  int64_t train_freq = 1;           // vector-env steps between updates
  int64_t gradient_steps = 1;       // per update; −1: as many as transitions collected
  Schedule learning_rate{3e-4, false};
  std::vector<int64_t> net_arch{256, 256};  // hidden layers of the policy (actor / Q-network)
  std::vector<int64_t> qf_net_arch;         // hidden layers of the critics; empty: net_arch
  nn::Activation activation = nn::Activation::kRelu;
  int64_t log_interval = 1000;  // environment steps between progress reports (and checkpoints)
  // Threads of the networks' matrix products (OpenBLAS). Two nearly halve an update of 256-wide
  // networks when the environments run in the calling thread; results are reproducible for a
  // fixed count, and another count may round differently.
  int learner_threads = 1;

  const std::vector<int64_t>& critic_arch() const {
    return qf_net_arch.empty() ? net_arch : qf_net_arch;
  }

  // Reads the keys above (learning_rate with learning_rate_schedule; activation as a name)
  // over this.
  void read(const Config& algo);
  // Raises Error naming the first out-of-range value.
  void validate(const std::string& where) const;
};

// The `preset` key of an algorithm's mapping, checked against `known` (the first is the
// default); an unknown preset raises Error naming the key and listing the known ones.
std::string read_preset(const Config& algo, const std::vector<std::string>& known,
                        const std::string& algorithm);

}  // namespace tendril::rl
