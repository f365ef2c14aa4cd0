#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tendril/core/config.hpp"

namespace tendril::apps {

// The arguments of one command: positional words, `--set key=value` overrides, and other
// `--flag value` / `--switch` options. Unknown flags are an error naming the flag.
struct CommandLine {
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string>> overrides;  // from --set key=value
  std::vector<std::pair<std::string, std::string>> options;    // --name value (value "" for switches)

  // `value_flags` take a value; `switch_flags` do not.
  static CommandLine parse(const std::vector<std::string>& args,
                           const std::vector<std::string>& value_flags,
                           const std::vector<std::string>& switch_flags);

  bool has(const std::string& flag) const;
  std::string value(const std::string& flag, const std::string& fallback) const;
  // Loads the experiment file (the first positional) and applies the overrides.
  Config load_config() const;
};

}  // namespace tendril::apps
