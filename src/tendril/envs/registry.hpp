#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/envs/env_description.hpp"

namespace tendril::envs {

class VecEnv;

// How to build one registered environment.
struct EnvSpec {
  // Versioned id, "Name-v<N>" or "Family/Name-v<N>"; a change of dynamics, reward or limits
  // gets a new version, never an edit of an existing one.
  std::string id;
  // Builds the environment from its parameters (the experiment's `env.params`). Reads what it
  // needs with Config::get/get_or; keys it leaves unread are rejected by Registry::make.
  std::function<std::unique_ptr<Env>(const Config& params)> factory;
  // Gymnasium's max_episode_steps: make() wraps the environment in a TimeLimit of this length.
  std::optional<int64_t> max_episode_steps;
  // One line for `tendril list envs`.
  std::string summary;
  // The environment in words (its class's static description()): entries of its spaces with
  // units, reward, episode end, parameters; printed by `tendril list envs --describe`.
  std::function<EnvDescription()> description = nullptr;
  // Optional: N environments of this id as one VecEnv that steps them together (a batched
  // learned model), behaving as N `make(id)` envs with episode statistics in a ThreadedVecEnv;
  // gets the time limit the single env would get.
  std::function<std::unique_ptr<VecEnv>(const Config& params, int num_envs,
                                        std::optional<int64_t> max_episode_steps)>
      vector_factory = nullptr;
  // The parameters it cannot default, as YAML, that `tendril list envs` and the tests that make
  // every registered id give it ("calibration: none" for the limb robot); empty for most.
  std::string example_params;
};

// Environment ids → factories. Filled explicitly (see builtin_envs.hpp), never by static
// registrars, so that nothing depends on the linker keeping an unreferenced object file.
class Registry {
 public:
  // Raises Error on a malformed or duplicate id, or a missing factory.
  void add(EnvSpec spec);

  bool contains(std::string_view id) const;
  // Raises Error naming the id and listing the registered ids when `id` is unknown.
  const EnvSpec& spec(std::string_view id) const;
  // Sorted.
  std::vector<std::string> ids() const;

  // Builds `id` from `params`. The optional parameter `max_episode_steps` (an integer ≥ 1)
  // overrides the registered time limit; `curriculum` (a mapping, CurriculumRule) wraps an
  // environment whose task has levels (CurriculumTask) in a Curriculum, inside the time limit.
  // Every other key of `params` must be read by the factory: an unknown one raises Error naming it
  // and the environment.
  std::unique_ptr<Env> make(std::string_view id, const Config& params = Config()) const;
  // `num_envs` envs of `id` through its vector_factory, with the parameters `make` reads;
  // nullptr when the id has none or `params` asks for a curriculum (per-env wrappers).
  std::unique_ptr<VecEnv> make_vector(std::string_view id, const Config& params,
                                      int num_envs) const;

 private:
  std::optional<int64_t> time_limit(const EnvSpec& spec, const Config& params) const;
  std::map<std::string, EnvSpec, std::less<>> specs_;
};

// The registry of every environment tendril ships (register_builtin_envs), built once on first
// use and never modified afterwards.
const Registry& builtin_registry();

// builtin_registry().make(id, params) and builtin_registry().ids().
std::unique_ptr<Env> make(std::string_view id, const Config& params = Config());
std::unique_ptr<VecEnv> make_vector(std::string_view id, const Config& params, int num_envs);
std::vector<std::string> registered_ids();

}  // namespace tendril::envs
