#include "tendril/core/env.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril {

void Info::set(std::string_view name, double value) {
  for (auto& entry : entries_) {
    if (entry.first == name) {
      entry.second = value;
      return;
    }
  }
  entries_.emplace_back(std::string(name), value);
}

std::optional<double> Info::get(std::string_view name) const {
  for (const auto& entry : entries_) {
    if (entry.first == name) return entry.second;
  }
  return std::nullopt;
}

void Env::save_state(SnapshotWriter& /*out*/) const {
  throw Error("this environment cannot save its state (no snapshot support)", "Env::save_state");
}

void Env::load_state(SnapshotReader& /*in*/) {
  throw Error("this environment cannot load a state (no snapshot support)", "Env::load_state");
}

void check_action(const Space& action_space, const Action& action, std::string_view who) {
  if (action.size() != action_space.size()) {
    throw Error("action has " + std::to_string(action.size()) + " components, expected " +
                    std::to_string(action_space.size()) + " (" + action_space.describe() + ")",
                std::string(who));
  }
  for (Eigen::Index i = 0; i < action.size(); ++i) {
    if (!std::isfinite(action[i])) {
      throw Error("action component " + std::to_string(i) + " is not finite", std::string(who));
    }
  }
  if (action_space.is_discrete() && !action_space.contains(action)) {
    throw Error("discrete action " + std::to_string(action[0]) + " outside [0, " +
                    std::to_string(action_space.n()) + ")",
                std::string(who));
  }
}

}  // namespace tendril
