#include "tendril/envs/env_description.hpp"

#include <memory>
#include <set>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs {

int entry_count(const std::vector<EnvDescription::Entries>& entries) {
  int count = 0;
  for (const EnvDescription::Entries& run : entries) count += run.count;
  return count;
}

std::vector<std::pair<std::string, std::string>> parameters_read(const Registry& registry,
                                                                 std::string_view id) {
  const std::string& example = registry.spec(id).example_params;
  const Config params = example.empty() ? Config() : Config::parse(example);
  registry.make(id, params);
  return params.resolved_entries();
}

namespace {

// Whether documented `key` names `read`: equal, or "prefix.*" with `read` below prefix.
bool covers(const std::string& key, const std::string& read) {
  if (key.size() > 2 && key.ends_with(".*")) {
    return read.starts_with(key.substr(0, key.size() - 1));
  }
  return key == read;
}

void check_entries(const std::vector<EnvDescription::Entries>& entries, const Space& space,
                   const std::string& which, std::vector<std::string>& problems) {
  if (entry_count(entries) != space.size()) {
    problems.push_back(which + ": the description covers " + std::to_string(entry_count(entries)) +
                       " entries, the space has " + std::to_string(space.size()));
  }
  for (const EnvDescription::Entries& run : entries) {
    if (run.name.empty() || run.unit.empty() || run.count < 1) {
      problems.push_back(which + " entry '" + run.name + "' needs a name, a unit and a count ≥ 1");
    }
  }
}

}  // namespace

std::vector<std::string> description_mismatches(const Registry& registry, std::string_view id) {
  const EnvSpec& spec = registry.spec(id);
  if (!spec.description) return {"no description"};
  const EnvDescription described = spec.description();
  std::vector<std::string> problems;
  const std::string& example = spec.example_params;
  const Config params = example.empty() ? Config() : Config::parse(example);
  const std::unique_ptr<Env> env = registry.make(id, params);
  check_entries(described.observation, env->observation_space(), "observation", problems);
  check_entries(described.action, env->action_space(), "action", problems);
  if (described.reward.empty()) problems.push_back("no reward text");
  if (described.episode_end.empty()) problems.push_back("no episode-end text");

  std::set<std::string> documented;
  for (const EnvDescription::Parameter& parameter : described.parameters) {
    if (!documented.insert(parameter.key).second) {
      problems.push_back("parameter '" + parameter.key + "' is documented twice");
    }
    if (parameter.meaning.empty()) {
      problems.push_back("parameter '" + parameter.key + "' has no meaning");
    }
  }
  const std::vector<std::pair<std::string, std::string>> read = params.resolved_entries();
  for (const auto& [key, value] : read) {
    bool found = false;
    for (const EnvDescription::Parameter& parameter : described.parameters) {
      if (!covers(parameter.key, key)) continue;
      found = true;
      if (parameter.optional) {
        problems.push_back("parameter '" + key + "' is read with the default " + value +
                           " but documented as optional (no default)");
      }
    }
    if (!found) {
      problems.push_back("parameter '" + key + "' (" + value + ") is read but not documented");
    }
  }
  for (const EnvDescription::Parameter& parameter : described.parameters) {
    if (parameter.optional) continue;
    bool found = false;
    for (const auto& entry : read) found = found || covers(parameter.key, entry.first);
    if (!found) {
      problems.push_back("parameter '" + parameter.key +
                         "' is documented with a default but the factory reads no such key");
    }
  }
  return problems;
}

}  // namespace tendril::envs
