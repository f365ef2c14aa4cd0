// The dynamics plugin's entry (dynamics_plugin.hpp): its table of installers and commands.
#include "dynamics_plugin.hpp"

#include "tendril/dynamics/env_model_loader.hpp"
#include "tendril/dynamics/policy_heads.hpp"

namespace {

void install() {
  // Environments around learned models open them from their `model` parameter.
  tendril::dynamics::install_model_loader();
  // Policies with a learned-model head (seed 001 ch. 5) are trained and loaded.
  tendril::dynamics::install_policy_heads();
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const tendril::apps::DynamicsPlugin*
tendril_dynamics_plugin() {
  static const tendril::apps::DynamicsPlugin plugin{
      .abi = tendril::apps::kDynamicsPluginAbi,
      .version = TENDRIL_VERSION,
      .install = install,
      .model_fit = tendril::apps::run_model_fit,
      .model_eval = tendril::apps::run_model_eval,
      .resume_stopped_fit = tendril::apps::continue_stopped_fit,
  };
  return &plugin;
}
