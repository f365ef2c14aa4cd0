// The program's side of the dynamics plugin (dynamics_plugin.hpp): finding and loading it, and
// the model commands, which hand over to it.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>

#include "commands.hpp"
#include "dynamics_plugin.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/model_file.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;

fs::path plugin_file() {
  if (const char* named = std::getenv("TENDRIL_DYNAMICS_PLUGIN"); named && *named) return named;
  // Beside the program, wherever it was built or installed (a pip installation puts both in
  // tendril/bin/).
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  require(!error, "cannot find the program's own file to look for its dynamics plugin beside it",
          "/proc/self/exe");
  return program.parent_path() / kDynamicsPluginFile;
}

const DynamicsPlugin& load_plugin() {
  const fs::path file = plugin_file();
  const std::string where = file.string();
  require(fs::exists(file),
          "not found: learned-model commands, environments and policy heads need this plugin "
          "(the dynamics layer, on LibTorch) beside the program; building the target tendril "
          "builds it, `pip install .` installs it",
          where);
  // Every symbol now: a plugin that does not fit this program fails here, not mid-command.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = dlerror();
    throw Error(std::string("cannot load the dynamics plugin: ") + (reason ? reason : "unknown"),
                where);
  }
  using Entry = const DynamicsPlugin* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, kDynamicsPluginEntry));
  require(entry != nullptr,
          std::string("is not a dynamics plugin (no ") + kDynamicsPluginEntry + ")", where);
  const DynamicsPlugin* plugin = entry();
  require(plugin != nullptr && plugin->abi == kDynamicsPluginAbi &&
              std::string(plugin->version) == TENDRIL_VERSION,
          "comes from another build of tendril (version " +
              std::string(plugin ? plugin->version : "?") + ", this program " + TENDRIL_VERSION +
              "): rebuild or reinstall both",
          where);
  // Never closed: models and heads made by it live until the program ends.
  return *plugin;
}

}  // namespace

const DynamicsPlugin& dynamics_plugin() {
  static std::mutex mutex;
  static const DynamicsPlugin* plugin = nullptr;
  std::lock_guard lock(mutex);
  if (plugin == nullptr) plugin = &load_plugin();
  return *plugin;
}

int model_fit_command(const Arguments& line) { return dynamics_plugin().model_fit(line); }

int model_eval_command(const Arguments& line) { return dynamics_plugin().model_eval(line); }

std::optional<int> resume_stopped_fit(const Arguments& line) {
  // Only a fit's run directory holds these files: other runs resume without the plugin.
  const fs::path run = line.positional.front();
  if (!fs::exists(run / dynamics::kFitCheckpointName) &&
      !fs::exists(run / dynamics::kModelFileName)) {
    return std::nullopt;
  }
  return dynamics_plugin().resume_stopped_fit(line);
}

}  // namespace tendril::apps
