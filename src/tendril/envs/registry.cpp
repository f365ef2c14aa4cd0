#include "tendril/envs/registry.hpp"

#include <regex>

#include "tendril/core/error.hpp"
#include "tendril/envs/builtin_envs.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/envs/wrappers/curriculum.hpp"
#include "tendril/envs/wrappers/time_limit.hpp"

namespace tendril::envs {

namespace {

bool well_formed(const std::string& id) {
  static const std::regex pattern(R"(([A-Za-z0-9_.]+/)*[A-Za-z0-9_.]+-v[0-9]+)");
  return std::regex_match(id, pattern);
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

void Registry::add(EnvSpec spec) {
  const std::string where = "envs::Registry::add";
  require(well_formed(spec.id), "environment id '" + spec.id + "' is not of the form Name-v<N>",
          where);
  require(!contains(spec.id), "environment id '" + spec.id + "' is already registered", where);
  require(static_cast<bool>(spec.factory), "environment '" + spec.id + "' has no factory", where);
  require(!spec.max_episode_steps || *spec.max_episode_steps >= 1,
          "environment '" + spec.id + "' has a time limit below 1", where);
  std::string id = spec.id;
  specs_.emplace(std::move(id), std::move(spec));
}

bool Registry::contains(std::string_view id) const { return specs_.find(id) != specs_.end(); }

const EnvSpec& Registry::spec(std::string_view id) const {
  const auto found = specs_.find(id);
  if (found == specs_.end()) {
    throw Error(
        "unknown environment id '" + std::string(id) + "'; registered ids: " + joined(ids()),
        "envs::make");
  }
  return found->second;
}

std::vector<std::string> Registry::ids() const {
  std::vector<std::string> names;
  names.reserve(specs_.size());
  for (const auto& entry : specs_) names.push_back(entry.first);
  return names;
}

std::optional<int64_t> Registry::time_limit(const EnvSpec& found, const Config& params) const {
  std::optional<int64_t> limit = found.max_episode_steps;
  if (params.has("max_episode_steps")) {
    limit = params.get<int64_t>("max_episode_steps");
    require(*limit >= 1, "max_episode_steps must be at least 1, got " + std::to_string(*limit),
            params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") +
                "max_episode_steps");
  }
  return limit;
}

std::unique_ptr<VecEnv> Registry::make_vector(std::string_view id, const Config& params,
                                              int num_envs) const {
  const EnvSpec& found = spec(id);
  if (!found.vector_factory || params.has("curriculum")) return nullptr;
  const std::optional<int64_t> limit = time_limit(found, params);
  std::unique_ptr<VecEnv> env = found.vector_factory(params, num_envs, limit);
  try {
    params.reject_unknown();
  } catch (const Error& e) {
    throw Error(e.what_wrong() + ", not a parameter of environment '" + found.id + "'", e.where());
  }
  return env;
}

std::unique_ptr<Env> Registry::make(std::string_view id, const Config& params) const {
  const EnvSpec& found = spec(id);
  const std::optional<int64_t> limit = time_limit(found, params);
  std::unique_ptr<Env> env = found.factory(params);
  if (params.has("curriculum")) {
    const CurriculumRule rule = CurriculumRule::from_config(params.child("curriculum"));
    if (dynamic_cast<CurriculumTask*>(env.get()) == nullptr) {
      throw Error("environment '" + found.id + "' has no curriculum levels",
                  params.source() + ": " + (params.path().empty() ? "" : params.path() + ".") +
                      "curriculum");
    }
    env = std::make_unique<Curriculum>(std::move(env), rule);
  }
  try {
    params.reject_unknown();
  } catch (const Error& e) {
    throw Error(e.what_wrong() + ", not a parameter of environment '" + found.id + "'", e.where());
  }
  if (limit) env = std::make_unique<TimeLimit>(std::move(env), *limit);
  return env;
}

const Registry& builtin_registry() {
  static const Registry registry = [] {
    Registry filled;
    register_builtin_envs(filled);
    return filled;
  }();
  return registry;
}

std::unique_ptr<Env> make(std::string_view id, const Config& params) {
  return builtin_registry().make(id, params);
}

std::unique_ptr<VecEnv> make_vector(std::string_view id, const Config& params, int num_envs) {
  return builtin_registry().make_vector(id, params, num_envs);
}

std::vector<std::string> registered_ids() { return builtin_registry().ids(); }

}  // namespace tendril::envs
