#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tendril/core/env.hpp"

namespace tendril::hardware {

struct DeployOptions {
  int episodes = 1;
  int max_steps = 0;          // per episode; 0: until the environment ends the episode
  uint64_t seed = 0;          // episode k resets with seed + k
  std::filesystem::path csv;  // one row per step (appended as it happens); empty: none
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by SIGINT): stop after this step
};

struct DeployResult {
  int episodes = 0;
  int steps = 0;
  std::vector<double> returns;
  std::string fault;  // the Error that ended the deployment, if one did
  bool stopped = false;
};

// Runs `actor` on `env` (a robot over its bridge, or any env) episode by episode. Each step's
// reward, flags and info go to the CSV as they happen. An Error (a bridge's safety action: a
// stale sensor, a lost link, a refused command) ends the deployment at once — the bridge has
// already commanded the robot safe — and is returned with what ran before it; `on_fault`, if
// given, runs first (an emergency stop, say).
DeployResult deploy(Env& env, const std::function<Action(const Observation&)>& actor,
                    const DeployOptions& options, const std::function<void()>& on_fault = {});

}  // namespace tendril::hardware
