#include "tendril/core/dynamics_layer.hpp"

#include <mutex>

namespace tendril {

namespace {

struct LayerSlot {
  std::mutex mutex;
  std::function<void()> load;
  bool loaded = false;
};

LayerSlot& slot() {
  static LayerSlot instance;
  return instance;
}

}  // namespace

void set_dynamics_layer_loader(std::function<void()> load) {
  std::lock_guard lock(slot().mutex);
  slot().load = std::move(load);
  slot().loaded = false;
}

bool load_dynamics_layer() {
  // Held while loading: the loader installs into other layers' tables (their own locks), never
  // back into this one.
  std::lock_guard lock(slot().mutex);
  if (!slot().load) return false;
  if (!slot().loaded) {
    slot().load();
    slot().loaded = true;
  }
  return true;
}

}  // namespace tendril
