#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tendril/core/scene.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/core/space.hpp"

namespace tendril {

// Named scalars reported by a step. Names are shared across environments where the meaning is
// the same (info_keys.hpp): "distance", "is_success", "cost", "nan".
class Info {
 public:
  void set(std::string_view name, double value);
  std::optional<double> get(std::string_view name) const;
  bool has(std::string_view name) const { return get(name).has_value(); }
  const std::vector<std::pair<std::string, double>>& entries() const { return entries_; }
  void clear() { entries_.clear(); }

 private:
  std::vector<std::pair<std::string, double>> entries_;
};

struct Step {
  Observation observation;
  double reward = 0.0;
  bool terminated = false;  // the task ended: goal, failure, non-finite state
  bool truncated = false;   // a time limit cut the episode; bootstrap from `observation`
  Info info;
};

// Everything a controller acts on, with Gymnasium's semantics (DESIGN.md, "The one interface").
// `step` raises Error for an action of the wrong size or with non-finite values; clipping to
// the bounds is the action wrapper's job, not the environment's.
class Env {
 public:
  virtual ~Env() = default;
  virtual const Space& observation_space() const = 0;
  virtual const Space& action_space() const = 0;
  virtual Observation reset(std::optional<uint64_t> seed = std::nullopt) = 0;
  virtual Step step(const Action& action) = 0;

  // Optional capabilities; the defaults say the environment lacks them.

  // Whether save_state/load_state work. An environment that supports snapshots restores, from
  // what save_state wrote, everything that evolves in time — physics, actuator and sensor
  // state, targets, counters, its random stream — so that the steps after load_state repeat
  // the steps after save_state exactly (safety rollouts, data collection from a given state,
  // checkpoints that resume mid-episode).
  virtual bool supports_snapshots() const { return false; }
  // Raise Error when snapshots are not supported; load_state raises Error on a snapshot of
  // another environment or size and then leaves the environment unchanged where it can.
  virtual void save_state(SnapshotWriter& out) const;
  virtual void load_state(SnapshotReader& in);

  // Fills `scene` (cleared by the caller) with what a viewer draws now and returns true, or
  // returns false when the environment has nothing to draw.
  virtual bool describe_scene(Scene& /*scene*/) const { return false; }

  // Releases what the environment holds outside the process (a hardware link); idempotent.
  virtual void close() {}
};

// Raises Error naming `who` unless `action` has the action space's size and finite values.
void check_action(const Space& action_space, const Action& action, std::string_view who);

}  // namespace tendril
