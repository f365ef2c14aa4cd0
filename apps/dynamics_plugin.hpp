#pragma once

#include <optional>

#include "cli/arguments.hpp"

namespace tendril::apps {

// What of the program needs the dynamics layer (learned models, LibTorch): the layer itself, its
// installers and the model commands, built as a plugin beside the program
// (libtendril_dynamics_plugin.so) and loaded at the first command or lookup that needs it
// (core/dynamics_layer.hpp), so that every other command starts without LibTorch. The plugin
// holds no layer below dynamics: it uses the program's, which the program exports, so there is
// one environment registry, one table of head kinds and one model loader at run time.
struct DynamicsPlugin {
  int abi;              // kDynamicsPluginAbi of the plugin's build
  const char* version;  // the plugin's version (VERSION)
  // Installs the model loader of learned-model environments and the learned-model head kinds.
  void (*install)();
  int (*model_fit)(const Arguments& line);
  int (*model_eval)(const Arguments& line);
  // `tendril resume RUN` of a model fit stopped with a checkpoint: the exit status, or nothing
  // when RUN holds no such fit.
  std::optional<int> (*resume_stopped_fit)(const Arguments& line);
};

// Raised when the table's layout changes, so that a stale plugin is refused, not called.
inline constexpr int kDynamicsPluginAbi = 1;
inline constexpr const char* kDynamicsPluginFile = "libtendril_dynamics_plugin.so";
// The plugin's one exported function, returning its table: extern "C" const DynamicsPlugin*
// tendril_dynamics_plugin().
inline constexpr const char* kDynamicsPluginEntry = "tendril_dynamics_plugin";

// The plugin, loaded at the first call: the file TENDRIL_DYNAMICS_PLUGIN names, else
// kDynamicsPluginFile in the program's directory. Raises Error naming the file when it is
// missing, cannot be loaded, or comes from another version.
const DynamicsPlugin& dynamics_plugin();

// The plugin's side of the model commands (dynamics_command.cpp).
int run_model_fit(const Arguments& line);
int run_model_eval(const Arguments& line);
std::optional<int> continue_stopped_fit(const Arguments& line);

}  // namespace tendril::apps
