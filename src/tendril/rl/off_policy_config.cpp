#include "tendril/rl/off_policy_config.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {
constexpr int64_t kMaxLayerSize = 65536;
constexpr int64_t kMaxLayerWeights = int64_t{1} << 26;
}  // namespace

void OffPolicyConfig::read(const Config& algo) {
  buffer_size = algo.get_or<int64_t>("buffer_size", buffer_size);
  learning_starts = algo.get_or<int64_t>("learning_starts", learning_starts);
  batch_size = algo.get_or<int64_t>("batch_size", batch_size);
  tau = algo.get_or<double>("tau", tau);
  gamma = algo.get_or<double>("gamma", gamma);
  train_freq = algo.get_or<int64_t>("train_freq", train_freq);
  gradient_steps = algo.get_or<int64_t>("gradient_steps", gradient_steps);
  learning_rate = read_schedule(algo, "learning_rate", learning_rate);
  net_arch = algo.get_or<std::vector<int64_t>>("net_arch", net_arch);
  qf_net_arch = algo.get_or<std::vector<int64_t>>("qf_net_arch", qf_net_arch);
  activation =
      nn::parse_activation(algo.get_or<std::string>("activation", nn::activation_name(activation)),
                           algo.where("activation"));
  log_interval = algo.get_or<int64_t>("log_interval", log_interval);
  learner_threads = algo.get_or<int>("learner_threads", learner_threads);
}

void OffPolicyConfig::validate(const std::string& where) const {
  require(buffer_size >= 1, "buffer_size must be at least 1", where);
  require(learning_starts >= 0, "learning_starts must be non-negative", where);
  require(batch_size >= 1, "batch_size must be at least 1", where);
  require(tau > 0.0 && tau <= 1.0, "tau must lie in (0, 1]", where);
  require(gamma >= 0.0 && gamma <= 1.0, "gamma must lie in [0, 1]", where);
  require(train_freq >= 1, "train_freq must be at least 1", where);
  require(gradient_steps >= -1, "gradient_steps must be -1 or non-negative", where);
  require(learning_rate.initial > 0.0, "learning_rate must be positive", where);
  const auto positive = [](const std::vector<int64_t>& sizes) {
    return std::all_of(sizes.begin(), sizes.end(), [](int64_t size) { return size >= 1; });
  };
  require(positive(net_arch) && positive(qf_net_arch), "layer sizes must be positive", where);
  // Bounds that keep a typo from asking for tens of gigabytes of weights.
  const auto bounded = [](const std::vector<int64_t>& sizes) {
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      if (sizes[i] > kMaxLayerSize) return false;
      if (i > 0 && sizes[i - 1] * sizes[i] > kMaxLayerWeights) return false;
    }
    return true;
  };
  require(bounded(net_arch) && bounded(qf_net_arch),
          "net_arch/qf_net_arch: layers of at most 65536 units and 2^26 weights between two "
          "layers",
          where);
  require(log_interval >= 1, "log_interval must be at least 1", where);
  require(learner_threads >= 1 && learner_threads <= 256, "learner_threads must lie in [1, 256]",
          where);
}

std::string read_preset(const Config& algo, const std::vector<std::string>& known,
                        const std::string& algorithm) {
  const std::string preset = algo.get_or<std::string>("preset", known.front());
  if (std::find(known.begin(), known.end(), preset) == known.end()) {
    std::string list;
    for (const std::string& name : known) list += (list.empty() ? "" : ", ") + name;
    throw Error("unknown " + algorithm + " preset '" + preset + "', expected one of " + list,
                algo.source() + ": " + (algo.path().empty() ? "" : algo.path() + ".") + "preset");
  }
  return preset;
}

}  // namespace tendril::rl
