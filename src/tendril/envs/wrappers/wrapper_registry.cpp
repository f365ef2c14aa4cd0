#include "tendril/envs/wrappers/wrapper_registry.hpp"

#include <functional>
#include <map>

#include "tendril/core/error.hpp"
#include "tendril/envs/wrappers/clip_action.hpp"
#include "tendril/envs/wrappers/history_stack.hpp"
#include "tendril/envs/wrappers/rescale_action.hpp"

namespace tendril::envs {

namespace {

// Builds a wrapper around `inner` from its keys; reads every key it accepts.
using WrapperFactory = std::function<std::unique_ptr<Env>(std::unique_ptr<Env>, const Config&)>;

const std::map<std::string, WrapperFactory>& factories() {
  static const std::map<std::string, WrapperFactory> table = {
      {"clip_action",
       [](std::unique_ptr<Env> inner, const Config&) -> std::unique_ptr<Env> {
         return std::make_unique<ClipAction>(std::move(inner));
       }},
      {"history_stack",
       [](std::unique_ptr<Env> inner, const Config& keys) -> std::unique_ptr<Env> {
         const int64_t length = keys.get<int64_t>("length");
         require(length >= 1 && length <= 100000,
                 "must be between 1 and 100000, got " + std::to_string(length),
                 keys.where("length"));
         return std::make_unique<HistoryStack>(std::move(inner), static_cast<int>(length));
       }},
      {"rescale_action",
       [](std::unique_ptr<Env> inner, const Config&) -> std::unique_ptr<Env> {
         return std::make_unique<RescaleAction>(std::move(inner));
       }},
  };
  return table;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

std::unique_ptr<Env> apply_wrappers(std::unique_ptr<Env> env, const std::vector<Config>& wrappers) {
  for (const Config& entry : wrappers) {
    const std::vector<std::string> names = entry.keys();
    const std::string where = entry.source() + ": " + entry.path();
    require(
        names.size() == 1,
        "each wrapper is a mapping of one name to its keys (e.g. {history_stack: {length: 4}}), "
        "got " +
            std::to_string(names.size()) + " names",
        where);
    const auto found = factories().find(names.front());
    if (found == factories().end()) {
      throw Error(
          "unknown wrapper '" + names.front() + "'; known wrappers: " + joined(wrapper_names()),
          entry.where(names.front()));
    }
    const Config keys = entry.child(names.front());
    try {
      env = found->second(std::move(env), keys);
    } catch (const Error& e) {
      // A wrapper that cannot wrap this environment (say, a history of a Discrete observation)
      // is named by its entry, not by its class.
      if (e.where().rfind(entry.source() + ": ", 0) == 0) throw;
      throw Error(e.what_wrong(), entry.where(names.front()));
    }
    keys.reject_unknown();
  }
  return env;
}

std::vector<std::string> wrapper_names() {
  std::vector<std::string> names;
  for (const auto& entry : factories()) names.push_back(entry.first);
  return names;
}

}  // namespace tendril::envs
