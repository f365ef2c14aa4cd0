// `tendril list-envs`: the registered environments.
#include <cstdio>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::apps {

int list_envs_command(const std::vector<std::string>& args) {
  CommandLine::parse(args, {}, {});
  const envs::Registry& registry = envs::builtin_registry();
  for (const std::string& id : registry.ids()) {
    const envs::EnvSpec& spec = registry.spec(id);
    const std::string limit =
        spec.max_episode_steps ? std::to_string(*spec.max_episode_steps) + " steps" : "no limit";
    std::printf("%-36s %-12s %s\n", id.c_str(), limit.c_str(), spec.summary.c_str());
  }
  return 0;
}

}  // namespace tendril::apps
