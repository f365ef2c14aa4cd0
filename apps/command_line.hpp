#pragma once

#include <cstdint>
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
  std::vector<std::pair<std::string, std::string>> options;  // --name value (value "" for switches)

  // `value_flags` take a value; `switch_flags` do not.
  static CommandLine parse(const std::vector<std::string>& args,
                           const std::vector<std::string>& value_flags,
                           const std::vector<std::string>& switch_flags);

  bool has(const std::string& flag) const;
  std::string value(const std::string& flag, const std::string& fallback) const;
  // The value of `flag` as a whole number in [min, max], `fallback` when the flag is absent.
  // All of the text must be the number: "3x", "1.5", "-1" for a count, "" are refused with an
  // Error naming the flag.
  int64_t integer(const std::string& flag, int64_t fallback, int64_t min, int64_t max) const;
  uint64_t unsigned_integer(const std::string& flag, uint64_t fallback) const;
  // Loads the experiment file (the first positional) and applies the overrides.
  Config load_config() const;
};

}  // namespace tendril::apps
