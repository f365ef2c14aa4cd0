#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tendril/hardware/arm_bridge.hpp"
#include "tendril/hardware/latency_stats.hpp"
#include "tendril/hardware/limb_bridge.hpp"

namespace tendril::hardware {

// What `tendril robot check` reports of a link: who answered the handshake (robot, firmware,
// limits), the round trip of PINGs, the robot's sensor rate (readings per second of its own
// clock), the control rate achieved (steps per wall-clock second with a command each), the
// command round trips, and what went wrong on the way.
struct LinkCheck {
  std::string robot;
  std::string firmware;
  std::vector<std::pair<std::string, int32_t>> limits;
  LatencyStats ping;
  LatencyStats command;
  int steps = 0;
  double robot_time_s = 0.0;  // the robot's clock over the steps
  double wall_time_s = 0.0;
  double sensor_rate_hz = 0.0;
  double control_rate_hz = 0.0;
  int readings_missed = 0;
  int safety_events = 0;

  std::string report() const;  // a few lines of text
};

// Checks a limb with `pings` PINGs, then `steps` steps with the coils off (each step one
// command and its reading). Errors of the bridge propagate.
LinkCheck check_limb(LimbBridge& bridge, int pings, int steps);
// The same for the pneumatic arm: vented chambers, one command per control period.
LinkCheck check_arm(ArmBridge& bridge, int pings, int steps);

}  // namespace tendril::hardware
