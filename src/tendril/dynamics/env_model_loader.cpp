#include "tendril/dynamics/env_model_loader.hpp"

#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/model_file.hpp"
#include "tendril/envs/learned/model_loader.hpp"

namespace tendril::dynamics {

void install_model_loader() {
  envs::install_dynamics_model_loader(
      [](const std::string& file_or_run) -> std::unique_ptr<envs::DynamicsModel> {
        return load_model(file_or_run);
      });
}

}  // namespace tendril::dynamics
