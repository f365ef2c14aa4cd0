#include "command_line.hpp"

#include <algorithm>
#include <charconv>

#include "tendril/core/error.hpp"

namespace tendril::apps {

namespace {
bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}
}  // namespace

CommandLine CommandLine::parse(const std::vector<std::string>& args,
                               const std::vector<std::string>& value_flags,
                               const std::vector<std::string>& switch_flags) {
  CommandLine line;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) {
      line.positional.push_back(arg);
      continue;
    }
    const std::string flag = arg.substr(2);
    if (flag == "set") {
      require(i + 1 < args.size(), "--set needs key=value", "command line");
      const std::string& assignment = args[++i];
      const std::size_t equals = assignment.find('=');
      require(equals != std::string::npos && equals > 0,
              "--set expects key=value, got '" + assignment + "'", "command line");
      line.overrides.emplace_back(assignment.substr(0, equals), assignment.substr(equals + 1));
    } else if (contains(value_flags, flag)) {
      require(i + 1 < args.size() && !args[i + 1].empty(), arg + " needs a value", "command line");
      require(args[i + 1].size() <= Config::kMaxValueBytes, arg + ": value too long",
              "command line");
      line.options.emplace_back(flag, args[++i]);
    } else if (contains(switch_flags, flag)) {
      line.options.emplace_back(flag, "");
    } else {
      throw Error("unknown option '" + arg + "'", "command line");
    }
  }
  return line;
}

bool CommandLine::has(const std::string& flag) const {
  return std::any_of(options.begin(), options.end(),
                     [&](const auto& o) { return o.first == flag; });
}

std::string CommandLine::value(const std::string& flag, const std::string& fallback) const {
  for (auto it = options.rbegin(); it != options.rend(); ++it) {
    if (it->first == flag) return it->second;
  }
  return fallback;
}

int64_t CommandLine::integer(const std::string& flag, int64_t fallback, int64_t min,
                             int64_t max) const {
  if (!has(flag)) return fallback;
  const std::string text = value(flag, "");
  int64_t number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  require(
      error == std::errc() && end == text.data() + text.size() && number >= min && number <= max,
      "--" + flag + " expects a whole number from " + std::to_string(min) + " to " +
          std::to_string(max) + ", got '" + text.substr(0, 40) + "'",
      "command line");
  return number;
}

uint64_t CommandLine::unsigned_integer(const std::string& flag, uint64_t fallback) const {
  if (!has(flag)) return fallback;
  const std::string text = value(flag, "");
  uint64_t number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  require(
      error == std::errc() && end == text.data() + text.size(),
      "--" + flag + " expects a whole number from 0 to 2^64-1, got '" + text.substr(0, 40) + "'",
      "command line");
  return number;
}

Config CommandLine::load_config() const {
  require(!positional.empty(), "missing the experiment file", "command line");
  Config config = Config::load_file(positional.front());
  for (const auto& [key, value] : overrides) config.set(key, value);
  return config;
}

}  // namespace tendril::apps
