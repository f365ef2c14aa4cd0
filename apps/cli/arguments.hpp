#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/config.hpp"

namespace tendril::apps {

struct CommandSpec;

// The parsed arguments of one command: positionals, `--set key=value` overrides and options,
// checked against the command's table entry. The typed readers refuse malformed values with an
// Error naming the option: a count must be all digits ("1e9", "3x", "" are refused), a number
// must be finite and all of the text.
class Arguments {
 public:
  // Raises Error (a usage error) for an unknown option, a missing value, a repeated option that
  // is not repeatable, --set where the command takes none, or a wrong number of positionals.
  static Arguments parse(const CommandSpec& command, const std::vector<std::string>& args);

  std::vector<std::string> raw;  // the arguments as given (for a data set's provenance line)
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string>> overrides;  // --set key=value, in order

  bool has(const std::string& option) const;
  // The value of a valued option, `fallback` when absent.
  std::string value(const std::string& option, const std::string& fallback = "") const;
  // Every value of a repeatable option, in order.
  std::vector<std::string> values(const std::string& option) const;
  // A whole number in [min, max].
  int64_t integer(const std::string& option, int64_t fallback, int64_t min, int64_t max) const;
  std::optional<int64_t> optional_integer(const std::string& option, int64_t min,
                                          int64_t max) const;
  uint64_t unsigned_integer(const std::string& option, uint64_t fallback) const;  // 0 … 2^64−1
  // A finite number in [min, max].
  double number(const std::string& option, double fallback, double min, double max) const;
  // Comma-separated finite numbers, each in [min, max].
  std::vector<double> numbers(const std::string& option, double min, double max) const;

  // Refuses two options given together.
  void exclusive(const std::string& first, const std::string& second) const;

  // Loads the first positional as a YAML file of `kind` (core/file_kind.hpp) and applies the
  // --set overrides.
  Config load_config(std::string_view kind) const;

 private:
  std::vector<std::pair<std::string, std::string>> options_;  // name, value ("" for switches)
};

// A usage error: the program prints it with a pointer to --help and exits with status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace tendril::apps
