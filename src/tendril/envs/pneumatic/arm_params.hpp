#pragma once

#include <string>

#include "tendril/core/config.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm_spec.hpp"

namespace tendril::envs::pneumatic {

// The parameters of PneumaticArm/Robot-v0 when it stands for the twin (env.params), all
// optional; lengths in mm and times in s at this boundary, SI inside:
//
//   scenario: S0                 # damage scenario S0–S4 (seed 002 §V-A)
//   damaged_chamber: 0           # which chamber of a damaged module (0, 1, 2)
//   damaged_fraction: 0          # of its command a disrupted chamber still reaches, [0, 1)
//   instance_seed: 0             # the manufactured robot: draws the imbalance
//   stochastic: true             # default of every effect's `enabled`
//   drift: {enabled, step_mm: 10.0, cap_mm: 40.0}
//   hysteresis: {enabled, width_bar: 0.1}
//   imbalance: {enabled, gain_spread: 0.1, eccentricity_mm: 2.0}
//   sensor_noise: {enabled, marker_sigma_mm: 0.2}
//   elasticity: {enabled, sigma: 0.1}    # per-trial factor 1 + σξ on each module's response
//   sensor_latency_s: 0.0        # whole multiples of the 10 ms sample period
//   magnitude_scale: 1.0         # multiplies every magnitude above (the calibration knob)
//   twin: {elements_per_module: 6, time_step_s: 5e-4, bend_deg_per_bar: 30,
//          extension_per_bar: 0.1, inflate_time_s: 0.15, deflate_time_s: 0.4,
//          ceiling_bar: 1.5, settle_time_s: 2.0}
//
// Raises tendril::Error naming the key (with its file) for a value of the wrong type or out
// of range; keys it does not know are left unread for the registry to reject.
physics::pneumatic::PneumaticArmSpec arm_spec_from(const Config& params);

// The keys arm_spec_from reads, each with `prefix` ("" or "robot.") before it.
std::vector<EnvDescription::Parameter> arm_parameters(const std::string& prefix);

// "<file>: <path>.<key>", for errors about one key.
std::string key_where(const Config& config, const std::string& key);

}  // namespace tendril::envs::pneumatic
