#include "tendril/envs/learned/model_loader.hpp"

#include <mutex>

#include "tendril/core/dynamics_layer.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs {

namespace {

struct LoaderSlot {
  std::mutex mutex;
  DynamicsModelLoader loader;
};

LoaderSlot& slot() {
  static LoaderSlot instance;
  return instance;
}

}  // namespace

void install_dynamics_model_loader(DynamicsModelLoader loader) {
  std::lock_guard lock(slot().mutex);
  slot().loader = std::move(loader);
}

std::unique_ptr<DynamicsModel> load_dynamics_model(const std::string& file_or_run,
                                                   std::string_view who) {
  auto installed = [] {
    std::lock_guard lock(slot().mutex);
    return slot().loader;
  };
  DynamicsModelLoader loader = installed();
  // A program that loads the dynamics layer on demand loads it now; it installs the loader.
  if (!loader && load_dynamics_layer()) loader = installed();
  if (!loader) {
    throw Error("cannot open the learned model '" + file_or_run +
                    "': this program was built without the dynamics layer",
                std::string(who));
  }
  std::unique_ptr<DynamicsModel> model = loader(file_or_run);
  require(model != nullptr, "the model loader returned nothing for '" + file_or_run + "'",
          std::string(who));
  return model;
}

}  // namespace tendril::envs
