#pragma once

#include <limits>
#include <optional>

#include "tendril/core/env.hpp"

namespace tendril::envs::testing {

// A deterministic environment for wrapper and vector tests. Its observation is
// [steps taken this episode, number of resets, seed of the last seeded reset (or −1)]; every
// step gives `reward`, records the action it received, and terminates once `terminate_at` steps
// were taken (never if 0), reporting is_success = 1 then.
class ScriptedEnv : public Env {
 public:
  struct Options {
    double reward = 1.0;
    int terminate_at = 0;
  };

  ScriptedEnv() : ScriptedEnv(Options{}) {}
  explicit ScriptedEnv(Options options)
      : options_(options),
        observation_space_(Space::box(3, -std::numeric_limits<float>::infinity(),
                                      std::numeric_limits<float>::infinity())),
        action_space_(Space::box(Eigen::Vector2f(-2.0f, 0.0f), Eigen::Vector2f(3.0f, 1.0f))) {}

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }

  Observation reset(std::optional<uint64_t> seed = std::nullopt) override {
    steps_ = 0;
    ++resets_;
    if (seed) last_seed_ = static_cast<float>(*seed);
    return observe();
  }

  Step step(const Action& action) override {
    check_action(action_space_, action, "ScriptedEnv");
    last_action_ = action;
    ++steps_;
    Step result;
    result.reward = options_.reward;
    result.terminated = options_.terminate_at > 0 && steps_ >= options_.terminate_at;
    if (result.terminated) result.info.set("is_success", 1.0);
    result.observation = observe();
    return result;
  }

  const Action& last_action() const { return last_action_; }

  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override {
    out.section("ScriptedEnv");
    out.put(static_cast<int64_t>(steps_));
    out.put(static_cast<int64_t>(resets_));
    out.put(static_cast<double>(last_seed_));
  }
  void load_state(SnapshotReader& in) override {
    in.section("ScriptedEnv");
    steps_ = static_cast<int>(in.get_int64());
    resets_ = static_cast<int>(in.get_int64());
    last_seed_ = static_cast<float>(in.get_double());
  }

 private:
  Observation observe() const {
    return Eigen::Vector3f(static_cast<float>(steps_), static_cast<float>(resets_), last_seed_);
  }

  Options options_;
  Space observation_space_;
  Space action_space_;
  int steps_ = 0;
  int resets_ = 0;
  float last_seed_ = -1.0f;
  Action last_action_;
};

}  // namespace tendril::envs::testing
