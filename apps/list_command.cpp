// `tendril list envs|algorithms|wrappers`: what the registries hold.
#include <cstdio>
#include <string>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/wrapper_registry.hpp"
#ifdef TENDRIL_WITH_RL
#include "tendril/rl/algorithm_registry.hpp"
#endif

namespace tendril::apps {

int list_envs_command(const Arguments&) {
  const envs::Registry& registry = envs::builtin_registry();
  for (const std::string& id : registry.ids()) {
    const envs::EnvSpec& spec = registry.spec(id);
    const std::string limit =
        spec.max_episode_steps ? std::to_string(*spec.max_episode_steps) + " steps" : "no limit";
    std::printf("%-36s %-12s %s\n", id.c_str(), limit.c_str(), spec.summary.c_str());
  }
  return 0;
}

int list_wrappers_command(const Arguments&) {
  for (const std::string& name : envs::wrapper_names()) std::printf("%s\n", name.c_str());
  return 0;
}

#ifdef TENDRIL_WITH_RL
int list_algorithms_command(const Arguments&) {
  for (const rl::AlgorithmSpec& spec : rl::registered_algorithms()) {
    std::printf("%-8s %s\n", spec.name.c_str(), spec.summary.c_str());
  }
  return 0;
}
#endif

}  // namespace tendril::apps
