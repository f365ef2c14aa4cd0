#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tendril::envs {

// What one registered environment is, in words: the meaning and unit of each entry of its
// observation and action, how its reward is computed, when its episodes end, and the parameters
// its factory reads. Each environment writes its own next to its class (a static `description()`)
// and names it in its registry line; `tendril list envs --describe` and docs/envs.md print it.
// Entries are for the environment as its default parameters make it; a parameter that changes a
// space's size says so in its meaning.
struct EnvDescription {
  // A run of `count` consecutive vector entries of one meaning ("node positions x, y, z of nodes
  // 0..16", 51 entries). `unit` is SI-style ("m", "rad/s", "N·m") or "1" for dimensionless.
  struct Entries {
    std::string name;
    std::string unit;
    int count = 1;
  };
  // One key of `env.params` (dotted below a mapping: "drift.enabled"). A key ending in ".*"
  // stands for every key below that mapping. `optional` marks a key read only when given
  // (no default: its absence selects another behaviour, said in `meaning`).
  struct Parameter {
    std::string key;
    std::string unit;
    std::string meaning;
    bool optional = false;
  };

  std::vector<Entries> observation;
  std::vector<Entries> action;
  // How a step's reward is computed (with the equation it implements where there is one).
  std::string reward;
  // When an episode terminates (a final state) or is truncated (time, budget).
  std::string episode_end;
  std::vector<Parameter> parameters;
};

// The number of vector entries `entries` covers.
int entry_count(const std::vector<EnvDescription::Entries>& entries);

class Registry;

// The parameters `id`'s factory reads when the registry makes it from its example parameters, as
// (key path, value used) pairs: the given ones and the defaults its reads fell back to
// (Config::resolved_entries). Raises what make raises.
std::vector<std::pair<std::string, std::string>> parameters_read(const Registry& registry,
                                                                 std::string_view id);

// Where `id`'s description disagrees with the environment its example parameters make: entry
// counts that differ from the spaces' sizes, entries without a name, unit or count, an empty
// reward or episode end, documented parameters the factory does not read with a default (or reads
// although marked optional), and parameters it reads that are not documented. Empty when they
// agree; one line per problem.
std::vector<std::string> description_mismatches(const Registry& registry, std::string_view id);

}  // namespace tendril::envs
