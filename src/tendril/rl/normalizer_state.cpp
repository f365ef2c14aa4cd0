#include "tendril/rl/normalizer_state.hpp"

#include <string>
#include <vector>

#include "tendril/envs/wrappers/normalize_observation.hpp"
#include "tendril/envs/wrappers/normalize_reward.hpp"

namespace tendril::rl {

void save_normalizers(envs::VecEnv& env, CheckpointWriter& writer) {
  for (int i = 0; i < env.num_envs(); ++i) {
    if (auto* normalizer = envs::find_wrapper<envs::NormalizeObservation>(env.env(i))) {
      writer.write_doubles("observation_normalizer_" + std::to_string(i),
                           normalizer->export_statistics());
    }
    if (auto* normalizer = envs::find_wrapper<envs::NormalizeReward>(env.env(i))) {
      writer.write_doubles("reward_normalizer_" + std::to_string(i),
                           normalizer->export_statistics());
    }
  }
}

std::function<void()> prepare_normalizers(envs::VecEnv& env, CheckpointReader& reader) {
  std::vector<std::function<void()>> installs;
  for (int i = 0; i < env.num_envs(); ++i) {
    if (auto* normalizer = envs::find_wrapper<envs::NormalizeObservation>(env.env(i))) {
      const auto values = reader.read_doubles("observation_normalizer_" + std::to_string(i));
      const auto statistics =
          envs::RunningMeanStd::from_array(values, normalizer->statistics().size());
      installs.push_back([normalizer, statistics] { normalizer->set_statistics(statistics); });
    }
    if (auto* normalizer = envs::find_wrapper<envs::NormalizeReward>(env.env(i))) {
      const auto values = reader.read_doubles("reward_normalizer_" + std::to_string(i));
      const auto statistics = envs::RunningMeanStd::from_array(values, 1);
      installs.push_back([normalizer, statistics] { normalizer->set_statistics(statistics); });
    }
  }
  return [installs] {
    for (const auto& install : installs) install();
  };
}

}  // namespace tendril::rl
