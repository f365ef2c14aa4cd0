#include "tendril/rl/export/policy_network.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/rl/actor_critic_policy.hpp"
#include "tendril/rl/dqn/q_greedy_policy.hpp"
#include "tendril/rl/sac/squashed_gaussian_policy.hpp"
#include "tendril/rl/td3/deterministic_policy.hpp"

namespace tendril::rl {

namespace {

using Network = PolicyNetwork;

Network::Activation exported(nn::Activation activation) {
  switch (activation) {
    case nn::Activation::kTanh:
      return Network::Activation::kTanh;
    case nn::Activation::kRelu:
      return Network::Activation::kRelu;
    case nn::Activation::kSoftsign:
      return Network::Activation::kSoftsign;
  }
  return Network::Activation::kNone;
}

// The layers of `mlp` whose parameters start at `parameters` (nn::DenseMlp's layout: each
// layer's out × in row-major weight, then its bias).
void append_layers(const nn::DenseMlp& mlp, const float* parameters,
                   std::vector<Network::Layer>& layers) {
  const std::vector<int64_t>& sizes = mlp.sizes();
  const float* at = parameters;
  for (std::size_t k = 0; k + 1 < sizes.size(); ++k) {
    Network::Layer layer;
    layer.inputs = sizes[k];
    layer.outputs = sizes[k + 1];
    layer.weight.assign(at, at + layer.inputs * layer.outputs);
    at += layer.inputs * layer.outputs;
    layer.bias.assign(at, at + layer.outputs);
    at += layer.outputs;
    const bool last = k + 2 == sizes.size();
    if (!last || mlp.activates_output()) {
      layer.activation = exported(mlp.hidden_activation());
    } else if (mlp.tanh_output()) {
      layer.activation = Network::Activation::kTanh;
    }
    layers.push_back(std::move(layer));
  }
}

// Keeps the first `rows` outputs of the last layer (the rest are not read by the action).
void keep_rows(Network::Layer& layer, int64_t rows) {
  layer.weight.resize(rows * layer.inputs);
  layer.bias.resize(rows);
  layer.outputs = rows;
}

void set_box_output(Network& network, const Space& action_space, Network::Output output) {
  network.output = output;
  network.action_size = action_space.size();
  network.low.assign(action_space.low().data(), action_space.low().data() + network.action_size);
  network.high.assign(action_space.high().data(), action_space.high().data() + network.action_size);
  if (output != Network::Output::kClip) {
    require(action_space.bounded(),
            "a squashed policy's action space must be bounded, not " + action_space.describe(),
            "rl::policy_network");
  }
}

void set_argmax_output(Network& network, int64_t choices) {
  network.output = Network::Output::kArgmax;
  network.action_size = 1;
  network.action_choices = choices;
}

void actor_critic_layers(const ActorCriticPolicy& policy, Network& network) {
  // nn::ActorCritic's layout: [policy trunk | policy head | log σ | value …].
  const nn::ActorCriticSpec& spec = policy.network().spec();
  const float* parameters = policy.parameters().data();
  int64_t latent = spec.observation_size;
  if (!spec.policy_layers.empty()) {
    std::vector<int64_t> sizes{spec.observation_size};
    sizes.insert(sizes.end(), spec.policy_layers.begin(), spec.policy_layers.end());
    const nn::DenseMlp trunk = nn::DenseMlp::trunk(sizes, spec.activation);
    append_layers(trunk, parameters, network.layers);
    parameters += trunk.parameter_count();
    latent = spec.policy_layers.back();
  }
  const nn::DenseMlp head =
      spec.policy_output_activation
          ? nn::DenseMlp::trunk({latent, spec.action_size}, *spec.policy_output_activation)
          : nn::DenseMlp({latent, spec.action_size}, spec.activation);
  append_layers(head, parameters, network.layers);
  if (spec.discrete) {
    set_argmax_output(network, spec.action_size);
  } else {
    set_box_output(network, policy.action_space(), Network::Output::kClip);
  }
}

void squashed_gaussian_layers(const SquashedGaussianPolicy& policy, Network& network) {
  if (policy.encoder().has_head()) {
    throw Error("a SAC actor with a history head ('" + policy.encoder().head().kind() +
                    "') is not a plain MLP; only policies without a head can be exported",
                "rl::policy_network");
  }
  append_layers(policy.network(), policy.parameters().data(), network.layers);
  const int64_t actions = policy.action_space().size();
  keep_rows(network.layers.back(), actions);  // μ; the rows after it are log σ
  if (policy.uses_sde()) {
    set_box_output(network, policy.action_space(), Network::Output::kClampTanhScale);
  } else {
    network.layers.back().activation = Network::Activation::kTanh;
    set_box_output(network, policy.action_space(), Network::Output::kScale);
  }
}

void deterministic_layers(const DeterministicPolicy& policy, Network& network) {
  append_layers(policy.network(), policy.parameters().data(), network.layers);
  set_box_output(network, policy.action_space(), Network::Output::kScale);
}

void q_greedy_layers(const QGreedyPolicy& policy, Network& network) {
  // The argmax of B·tanh(z) is that of z: a bounded head's tanh does not change the choice,
  // but it is kept so that the network's outputs are the Q-values up to the factor B.
  append_layers(policy.network(), policy.parameters().data(), network.layers);
  set_argmax_output(network, policy.action_space().n());
}

void activate(Network::Activation activation, std::vector<float>& values) {
  for (float& v : values) {
    switch (activation) {
      case Network::Activation::kTanh:
        v = std::tanh(v);
        break;
      case Network::Activation::kRelu:
        v = std::max(v, 0.0f);
        break;
      case Network::Activation::kSoftsign:
        v = v / (1.0f + std::abs(v));
        break;
      case Network::Activation::kNone:
        break;
    }
  }
}

}  // namespace

int64_t PolicyNetwork::parameter_count() const {
  int64_t count = 0;
  for (const Layer& layer : layers) count += layer.outputs * (layer.inputs + 1);
  return count;
}

PolicyNetwork policy_network(const Policy& policy) {
  Network network;
  network.kind = policy.kind();
  network.observation_size = policy.observation_space().size();
  if (const auto& normalization = policy.observation_normalization()) {
    const envs::RunningMeanStd& statistics = normalization->statistics;
    for (int i = 0; i < statistics.size(); ++i) {
      network.mean.push_back(static_cast<float>(statistics.mean()[i]));
      network.scale.push_back(
          static_cast<float>(1.0 / std::sqrt(statistics.var()[i] + normalization->epsilon)));
    }
    network.clip = static_cast<float>(normalization->clip);
  }
  if (const auto* p = dynamic_cast<const ActorCriticPolicy*>(&policy)) {
    actor_critic_layers(*p, network);
  } else if (const auto* p = dynamic_cast<const SquashedGaussianPolicy*>(&policy)) {
    squashed_gaussian_layers(*p, network);
  } else if (const auto* p = dynamic_cast<const DeterministicPolicy*>(&policy)) {
    deterministic_layers(*p, network);
  } else if (const auto* p = dynamic_cast<const QGreedyPolicy*>(&policy)) {
    q_greedy_layers(*p, network);
  } else {
    throw Error("policies of kind '" + policy.kind() + "' cannot be exported",
                "rl::policy_network");
  }
  return network;
}

Action evaluate_policy_network(const PolicyNetwork& network, const Observation& observation) {
  require(observation.size() == network.observation_size,
          "the observation has " + std::to_string(observation.size()) +
              " components, the policy expects " + std::to_string(network.observation_size),
          "rl::evaluate_policy_network");
  std::vector<float> x(observation.data(), observation.data() + observation.size());
  if (!network.mean.empty()) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] = std::clamp((x[i] - network.mean[i]) * network.scale[i], -network.clip, network.clip);
    }
  }
  for (const PolicyNetwork::Layer& layer : network.layers) {
    std::vector<float> y(layer.bias);
    for (int64_t r = 0; r < layer.outputs; ++r) {
      float sum = 0.0f;
      for (int64_t c = 0; c < layer.inputs; ++c) sum += layer.weight[r * layer.inputs + c] * x[c];
      y[r] += sum;
    }
    activate(layer.activation, y);
    x = std::move(y);
  }
  Action action(network.action_size);
  switch (network.output) {
    case PolicyNetwork::Output::kArgmax:
      action[0] = static_cast<float>(std::max_element(x.begin(), x.end()) - x.begin());
      break;
    case PolicyNetwork::Output::kClip:
      for (int64_t i = 0; i < network.action_size; ++i) {
        action[i] = std::clamp(x[i], network.low[i], network.high[i]);
      }
      break;
    case PolicyNetwork::Output::kClampTanhScale:
    case PolicyNetwork::Output::kScale:
      for (int64_t i = 0; i < network.action_size; ++i) {
        float a = x[i];
        if (network.output == PolicyNetwork::Output::kClampTanhScale) {
          a = std::tanh(std::clamp(a, -2.0f, 2.0f));
        }
        a = std::clamp(a, -1.0f, 1.0f);
        const float half_range = 0.5f * (network.high[i] - network.low[i]);
        action[i] = network.low[i] + (a + 1.0f) * half_range;
      }
      break;
  }
  return action;
}

std::string output_name(PolicyNetwork::Output output) {
  switch (output) {
    case PolicyNetwork::Output::kClip:
      return "clip";
    case PolicyNetwork::Output::kScale:
      return "scale";
    case PolicyNetwork::Output::kClampTanhScale:
      return "clamp_tanh_scale";
    case PolicyNetwork::Output::kArgmax:
      return "argmax";
  }
  return "?";
}

std::string activation_name(PolicyNetwork::Activation activation) {
  switch (activation) {
    case PolicyNetwork::Activation::kNone:
      return "none";
    case PolicyNetwork::Activation::kTanh:
      return "tanh";
    case PolicyNetwork::Activation::kRelu:
      return "relu";
    case PolicyNetwork::Activation::kSoftsign:
      return "softsign";
  }
  return "?";
}

}  // namespace tendril::rl
