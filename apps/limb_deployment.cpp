#include "limb_deployment.hpp"

#include <array>
#include <optional>

#include "tendril/core/error.hpp"
#include "tendril/envs/sma_limb/deployment_calibration.hpp"

namespace tendril::apps {

LimbDeployment limb_deployment(const Arguments& line, const Config* trained_env_params,
                               const std::string& command) {
  std::optional<std::string> trained;
  if (trained_env_params != nullptr && trained_env_params->has("model")) {
    trained = envs::sma_limb::model_calibration(trained_env_params->get<std::string>("model"));
  }
  LimbDeployment deployment;
  const std::string limb = line.value("limb", "stiff");
  deployment.calibration = envs::sma_limb::deployment_calibration(
      line.value("calibration", ""), trained, limb, "tendril " + command);
  deployment.params.set("limb", limb);
  deployment.params.set("calibration", deployment.calibration);
  // The keys the command's own options set are refused here, so that each has one source.
  static const std::array<const char*, 4> own = {"limb", "calibration", "tip_mass", "seed"};
  const std::string prefix = "env.params.";
  for (const auto& [key, value] : line.overrides) {
    if (key.rfind(prefix, 0) != 0) {
      throw UsageError("--set sets only the robot's env.params.<name>, got '" + key + "'");
    }
    const std::string name = key.substr(prefix.size());
    for (const char* option : own) {
      if (name == option) {
        throw UsageError("--set " + key + ": use the command's own option for " + name);
      }
    }
    deployment.params.set(name, value);
  }
  return deployment;
}

}  // namespace tendril::apps
