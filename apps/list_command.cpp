// `tendril list envs|algorithms|wrappers`: what the registries hold.
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/wrapper_registry.hpp"
#ifdef TENDRIL_WITH_RL
#include "tendril/rl/algorithm_registry.hpp"
#endif

namespace tendril::apps {

namespace {

std::string limit_text(const envs::EnvSpec& spec) {
  return spec.max_episode_steps ? std::to_string(*spec.max_episode_steps) + " steps" : "no limit";
}

// An environment as its default parameters make it: its spaces and the info values a step
// reports (one step from reset(0) with a sampled action); or why it needs parameters.
struct Description {
  std::string observation, action, info, needs;
  std::string made_with;  // the parameters it cannot default, when it has such
};

Description describe(const envs::Registry& registry, const std::string& id) {
  Description d;
  try {
    const std::string& example = registry.spec(id).example_params;
    const std::unique_ptr<Env> env =
        registry.make(id, example.empty() ? Config() : Config::parse(example));
    if (!example.empty()) d.made_with = example;
    d.observation = env->observation_space().describe();
    d.action = env->action_space().describe();
    env->reset(0);
    Rng rng(0);
    const Step step = env->step(env->action_space().sample(rng));
    for (const auto& [name, value] : step.info.entries()) {
      d.info += (d.info.empty() ? "" : ", ") + name;
    }
  } catch (const Error& e) {
    d.needs = e.what();
  }
  return d;
}

// The rows of an environment's description after its summary: (label, value).
std::vector<std::pair<std::string, std::string>> description_rows(const envs::EnvSpec& spec,
                                                                  const Description& d) {
  std::vector<std::pair<std::string, std::string>> rows = {{"time limit", limit_text(spec)}};
  if (!d.made_with.empty()) rows.emplace_back("made with", d.made_with);
  if (!d.needs.empty()) {
    rows.emplace_back("needs", d.needs);
    return rows;
  }
  rows.emplace_back("observation", d.observation);
  rows.emplace_back("action", d.action);
  rows.emplace_back("info", d.info.empty() ? "none" : d.info);
  return rows;
}

}  // namespace

int list_envs_command(const Arguments& line) {
  const envs::Registry& registry = envs::builtin_registry();
  std::vector<std::string> ids = line.positional.empty() ? registry.ids() : line.positional;
  for (const std::string& id : ids) {
    if (!registry.contains(id)) throw UsageError("no environment '" + id + "' (tendril list envs)");
  }
  if (line.has("markdown")) {
    std::printf(
        "# Environments\n\nGenerated from the registry (`tendril list envs --markdown`): each id "
        "as its default parameters make it; `tendril list envs --describe ID` prints the same. "
        "Spaces are written Box(size, [low, high]) or Discrete(n); the info values are those a "
        "step reports (`tendril run` averages them per step and at episodes' ends).\n");
    for (const std::string& id : ids) {
      const envs::EnvSpec& spec = registry.spec(id);
      const Description d = describe(registry, id);
      std::printf("\n## %s\n\n%s.\n\n| | |\n|---|---|\n", id.c_str(), spec.summary.c_str());
      for (const auto& [label, value] : description_rows(spec, d)) {
        // Parameters and spaces as code; the time limit, info names and reasons as text.
        const bool code = label == "made with" || label == "observation" || label == "action";
        std::printf(code ? "| %s | `%s` |\n" : "| %s | %s |\n", label.c_str(), value.c_str());
      }
    }
    return 0;
  }
  for (const std::string& id : ids) {
    const envs::EnvSpec& spec = registry.spec(id);
    if (!line.has("describe")) {
      std::printf("%-36s %-12s %s\n", id.c_str(), limit_text(spec).c_str(), spec.summary.c_str());
      continue;
    }
    const Description d = describe(registry, id);
    std::printf("%s: %s\n", id.c_str(), spec.summary.c_str());
    for (const auto& [label, value] : description_rows(spec, d)) {
      std::printf("  %-12s %s\n", label.c_str(), value.c_str());
    }
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
