#pragma once

#include <memory>
#include <optional>

#include "tendril/core/env.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs {

// An Env that owns another and changes one aspect of it; everything it does not override is
// passed through to the inner environment unchanged.
class Wrapper : public Env {
 public:
  explicit Wrapper(std::unique_ptr<Env> inner) : inner_(std::move(inner)) {
    require(inner_ != nullptr, "cannot wrap a null environment", "envs::Wrapper");
  }

  const Space& observation_space() const override { return inner_->observation_space(); }
  const Space& action_space() const override { return inner_->action_space(); }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override {
    return inner_->reset(seed);
  }
  Step step(const Action& action) override { return inner_->step(action); }
  // A wrapper with state of its own writes its section and then the inner environment's.
  bool supports_snapshots() const override { return inner_->supports_snapshots(); }
  void save_state(SnapshotWriter& out) const override { inner_->save_state(out); }
  void load_state(SnapshotReader& in) override { inner_->load_state(in); }
  bool describe_scene(Scene& scene) const override { return inner_->describe_scene(scene); }
  void close() override { inner_->close(); }

  Env& inner() { return *inner_; }
  const Env& inner() const { return *inner_; }

 protected:
  std::unique_ptr<Env> inner_;
};

// The outermost wrapper of type W in the chain that starts at `env` (which may itself be a W),
// or nullptr: how a caller reaches, say, the task inside its wrappers to inspect its state.
template <typename W>
W* find_wrapper(Env& env) {
  Env* current = &env;
  while (current != nullptr) {
    if (auto* found = dynamic_cast<W*>(current)) return found;
    auto* wrapper = dynamic_cast<Wrapper*>(current);
    current = wrapper != nullptr ? &wrapper->inner() : nullptr;
  }
  return nullptr;
}

}  // namespace tendril::envs
