#pragma once

#include <optional>
#include <string>

#include "cli/arguments.hpp"
#include "tendril/core/config.hpp"

namespace tendril::apps {

// The SMA limb a deployment command (`track`, `safety diamond`) runs a controller on:
// SmaLimb/Robot-v0's parameters from --limb, --calibration and `--set env.params.KEY=VALUE`
// (the robot's other parameters, e.g. backend=bridge and bridge.port=/dev/ttyACM0, as
// `tendril run` takes them). The calibration follows envs::sma_limb::deployment_calibration:
// the one the controller's learned model (`trained_env_params`' `model`, if any) was fitted
// with, unless --calibration names the same table; without a model, --calibration is required.
struct LimbDeployment {
  Config params;
  std::string calibration;  // a file, or "none"
};

LimbDeployment limb_deployment(const Arguments& line, const Config* trained_env_params,
                               const std::string& command);

}  // namespace tendril::apps
