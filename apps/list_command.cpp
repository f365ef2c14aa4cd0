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
  std::string made_with;       // the parameters it cannot default, when it has such
  envs::EnvDescription words;  // its own description (empty when it has none)
  std::vector<std::pair<std::string, std::string>> read;  // parameters its factory read
};

Description describe(const envs::Registry& registry, const std::string& id) {
  Description d;
  try {
    const std::string& example = registry.spec(id).example_params;
    const Config params = example.empty() ? Config() : Config::parse(example);
    const std::unique_ptr<Env> env = registry.make(id, params);
    if (!example.empty()) d.made_with = example;
    d.read = params.resolved_entries();
    if (registry.spec(id).description) d.words = registry.spec(id).description();
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
  if (!d.words.reward.empty()) rows.emplace_back("reward", d.words.reward);
  if (!d.words.episode_end.empty()) rows.emplace_back("episode end", d.words.episode_end);
  return rows;
}

// "[3]" or "[3..35]": the vector indices of each run of entries.
std::vector<std::string> index_ranges(const std::vector<envs::EnvDescription::Entries>& entries) {
  std::vector<std::string> ranges;
  int first = 0;
  for (const auto& run : entries) {
    const int last = first + run.count - 1;
    ranges.push_back("[" + std::to_string(first) +
                     (run.count > 1 ? ".." + std::to_string(last) : std::string()) + "]");
    first = last + 1;
  }
  return ranges;
}

// `text` for a Markdown table cell.
std::string cell(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

// The value `p` was read with (given or its default); "—" for an optional key not given.
std::string parameter_value(const Description& d, const envs::EnvDescription::Parameter& p,
                            bool markdown) {
  for (const auto& [key, value] : d.read) {
    if (key == p.key) return markdown ? "`" + cell(value) + "`" : value;
  }
  return p.optional ? "—" : "";
}

void print_markdown_details(const Description& d) {
  const envs::EnvDescription& words = d.words;
  for (const auto& [title, entries] :
       {std::pair{"Observation", &words.observation}, std::pair{"Action", &words.action}}) {
    if (entries->empty()) continue;
    std::printf("\n%s:\n\n| entries | meaning | unit |\n|---|---|---|\n", title);
    const std::vector<std::string> ranges = index_ranges(*entries);
    for (std::size_t i = 0; i < entries->size(); ++i) {
      std::printf("| %s | %s | %s |\n", ranges[i].c_str(), cell((*entries)[i].name).c_str(),
                  cell((*entries)[i].unit).c_str());
    }
  }
  if (words.parameters.empty()) return;
  std::printf(
      "\nParameters (`env.params`):\n\n| key | default | unit | meaning |\n|---|---|---|---|\n");
  for (const auto& p : words.parameters) {
    std::printf("| `%s` | %s | %s | %s |\n", p.key.c_str(), parameter_value(d, p, true).c_str(),
                cell(p.unit).c_str(), cell(p.meaning).c_str());
  }
}

void print_text_details(const Description& d) {
  const envs::EnvDescription& words = d.words;
  for (const auto& [title, entries] : {std::pair{"observation entries", &words.observation},
                                       std::pair{"action entries", &words.action}}) {
    if (entries->empty()) continue;
    std::printf("  %s\n", title);
    const std::vector<std::string> ranges = index_ranges(*entries);
    for (std::size_t i = 0; i < entries->size(); ++i) {
      std::printf("    %-10s %s (%s)\n", ranges[i].c_str(), (*entries)[i].name.c_str(),
                  (*entries)[i].unit.c_str());
    }
  }
  if (words.parameters.empty()) return;
  std::printf("  parameters\n");
  for (const auto& p : words.parameters) {
    const std::string value = parameter_value(d, p, false);
    // Dimensionless values go bare ("goal_bonus: 1", not "1 1").
    const bool unit = !p.unit.empty() && p.unit != "1" && value != "—";
    std::printf("    %s: %s%s  %s\n", p.key.c_str(), value.c_str(),
                unit ? (" " + p.unit).c_str() : "", p.meaning.c_str());
  }
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
        "step reports (`tendril run` averages them per step and at episodes' ends). Entries are "
        "numbered from 0, and unit 1 means dimensionless. A parameter's default is the value its "
        "environment read when made as listed; — marks a key read only when given, whose meaning "
        "says what applies without it. Every environment also takes `max_episode_steps` (over its "
        "time limit) and, when its task has levels, `curriculum`.\n");
    for (const std::string& id : ids) {
      const envs::EnvSpec& spec = registry.spec(id);
      const Description d = describe(registry, id);
      std::printf("\n## %s\n\n%s.\n\n| | |\n|---|---|\n", id.c_str(), spec.summary.c_str());
      for (const auto& [label, value] : description_rows(spec, d)) {
        // Parameters and spaces as code; the time limit, info names and reasons as text.
        const bool code = label == "made with" || label == "observation" || label == "action";
        std::printf(code ? "| %s | `%s` |\n" : "| %s | %s |\n", label.c_str(),
                    (code ? value : cell(value)).c_str());
      }
      if (d.needs.empty()) print_markdown_details(d);
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
    if (d.needs.empty()) print_text_details(d);
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
