#include "tendril/rl/normalizer_state.hpp"

#include <string>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

constexpr const char* kObservationStatistics = "normalizer_observation_statistics";
constexpr const char* kReturnStatistics = "normalizer_return_statistics";
constexpr const char* kReturns = "normalizer_returns";

// Whether the checkpoint holds `key` exactly when `env` normalizes that quantity.
void expect_presence(CheckpointReader& reader, const char* key, bool normalized,
                     const std::string& what) {
  const bool present = reader.contains(key);
  if (present == normalized) return;
  throw Error(present ? "the checkpoint holds " + what + " statistics ('" + key +
                            "') but this environment does not normalize " + what + "s"
                      : "this environment normalizes " + what +
                            "s but the checkpoint holds no statistics for them ('" + key + "')",
              reader.file().string());
}

// RunningMeanStd::from_array, with the checkpoint and key named in its error.
envs::RunningMeanStd read_statistics(CheckpointReader& reader, const char* key, int size) {
  const std::vector<double> values = reader.read_doubles(key);
  try {
    return envs::RunningMeanStd::from_array(values, size);
  } catch (const Error& error) {
    throw Error(std::string("'") + key + "': " + error.what_wrong(), reader.file().string());
  }
}

}  // namespace

void save_normalizers(const envs::VecEnv& env, CheckpointWriter& writer) {
  const envs::VecNormalize* normalizer = env.normalizer();
  if (normalizer == nullptr) return;
  if (normalizer->options().normalize_observation) {
    writer.write_doubles(kObservationStatistics, normalizer->observation_statistics().to_array());
  }
  if (normalizer->options().normalize_reward) {
    writer.write_doubles(kReturnStatistics, normalizer->return_statistics().to_array());
    const Eigen::VectorXd& returns = normalizer->returns();
    writer.write_doubles(kReturns,
                         std::vector<double>(returns.data(), returns.data() + returns.size()));
  }
}

std::function<void()> prepare_normalizers(envs::VecEnv& env, CheckpointReader& reader) {
  envs::VecNormalize* normalizer = env.normalizer();
  const bool observations = normalizer != nullptr && normalizer->options().normalize_observation;
  const bool rewards = normalizer != nullptr && normalizer->options().normalize_reward;
  expect_presence(reader, kObservationStatistics, observations, "observation");
  expect_presence(reader, kReturnStatistics, rewards, "reward");
  std::vector<std::function<void()>> installs;
  const std::string where = reader.file().string();
  if (observations) {
    const envs::RunningMeanStd statistics = read_statistics(
        reader, kObservationStatistics, normalizer->observation_statistics().size());
    installs.push_back(
        [normalizer, statistics] { normalizer->set_observation_statistics(statistics); });
  }
  if (rewards) {
    const envs::RunningMeanStd statistics = read_statistics(reader, kReturnStatistics, 1);
    const std::vector<double> values = reader.read_doubles(kReturns);
    require(values.size() == static_cast<std::size_t>(env.num_envs()),
            "the checkpoint holds running returns of " + std::to_string(values.size()) +
                " environments, this run has " + std::to_string(env.num_envs()),
            where);
    const Eigen::VectorXd returns = Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
    require(returns.allFinite(), "the checkpoint's running returns are not all finite", where);
    installs.push_back(
        [normalizer, statistics, returns] { normalizer->set_return_state(statistics, returns); });
  }
  return [installs] {
    for (const auto& install : installs) install();
  };
}

}  // namespace tendril::rl
