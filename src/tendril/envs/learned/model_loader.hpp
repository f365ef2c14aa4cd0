#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "tendril/envs/learned/dynamics_model.hpp"

namespace tendril::envs {

// Opens a trained model from a model file or a run directory holding one.
using DynamicsModelLoader =
    std::function<std::unique_ptr<DynamicsModel>(const std::string& file_or_run)>;

// How environments built from a `model` parameter open their model. Models are implemented above
// envs/ (dynamics/), so the program installs the loader once at start-up
// (dynamics::install_model_loader) before it builds environments, or loads the layer on demand
// (core/dynamics_layer.hpp); the layers below never see LibTorch. Installing again replaces the
// loader (tests install scripted models).
void install_dynamics_model_loader(DynamicsModelLoader loader);

// Opens `file_or_run` with the installed loader, loading the dynamics layer first when the
// program loads it on demand; raises Error naming `who` when no loader is installed (a program
// built without the dynamics layer) or the loader fails.
std::unique_ptr<DynamicsModel> load_dynamics_model(const std::string& file_or_run,
                                                   std::string_view who);

}  // namespace tendril::envs
