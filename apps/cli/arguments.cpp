#include "cli/arguments.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "cli/command.hpp"
#include "cli/suggestion.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"

namespace tendril::apps {

namespace {

const OptionSpec* find_option(const CommandSpec& command, const std::string& name) {
  for (const OptionSpec& option : command.options) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

const OptionSpec* find_short(const CommandSpec& command, char name) {
  for (const OptionSpec& option : command.options) {
    if (option.short_name != '\0' && option.short_name == name) return &option;
  }
  return nullptr;
}

std::string shown(const std::string& text) {
  return text.size() > 40 ? text.substr(0, 40) + "..." : text;
}

[[noreturn]] void usage(const std::string& message) { throw UsageError(message); }

std::string range_text(int64_t min, int64_t max) {
  if (max == INT64_MAX) return "a whole number ≥ " + std::to_string(min);
  return "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
}

}  // namespace

Arguments Arguments::parse(const CommandSpec& command, const std::vector<std::string>& args) {
  Arguments parsed;
  parsed.raw = args;
  if (command.passthrough) {
    parsed.positional = args;
    return parsed;
  }
  bool only_positionals = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (only_positionals || arg == "-" || arg.empty() || arg[0] != '-') {
      parsed.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      only_positionals = true;
      continue;
    }
    std::string name;
    std::optional<std::string> inline_value;
    const OptionSpec* option = nullptr;
    if (arg.rfind("--", 0) == 0) {
      name = arg.substr(2);
      const std::size_t equals = name.find('=');
      if (equals != std::string::npos) {
        inline_value = name.substr(equals + 1);
        name.resize(equals);
      }
      if (name == "set") {
        if (!command.takes_set) {
          usage("--set: '" + command.name() +
                "' reads no YAML file; its settings are options (see --help)");
        }
        std::string assignment;
        if (inline_value) {
          assignment = *inline_value;
        } else {
          if (i + 1 >= args.size()) usage("--set needs key=value");
          assignment = args[++i];
        }
        const std::size_t equals_sign = assignment.find('=');
        if (equals_sign == std::string::npos || equals_sign == 0) {
          usage("--set expects key=value, got '" + shown(assignment) + "'");
        }
        if (assignment.size() > Config::kMaxValueBytes)
          usage("--set: value too long (at most " + std::to_string(Config::kMaxValueBytes) +
                " characters)");
        parsed.overrides.emplace_back(assignment.substr(0, equals_sign),
                                      assignment.substr(equals_sign + 1));
        continue;
      }
      option = find_option(command, name);
    } else if (arg.size() == 2) {
      option = find_short(command, arg[1]);
      name = option ? option->name : arg.substr(1);
    }
    if (option == nullptr) {
      std::vector<std::string> names;
      for (const OptionSpec& o : command.options) names.push_back(o.name);
      if (command.takes_set) names.push_back("set");
      const std::string close = closest(name, names);
      usage("unknown option '" + shown(arg) + "'" +
            (close.empty() ? "" : " (did you mean --" + close + "?)"));
    }
    if (!option->repeatable && parsed.has(option->name)) {
      usage("--" + option->name + " given twice");
    }
    if (option->value.empty()) {
      if (inline_value) usage("--" + option->name + " takes no value");
      parsed.options_.emplace_back(option->name, "");
      continue;
    }
    std::string value;
    if (inline_value) {
      value = *inline_value;
    } else {
      if (i + 1 >= args.size())
        usage("--" + option->name + " needs a value (" + option->value + ")");
      value = args[++i];
    }
    if (value.empty()) usage("--" + option->name + " needs a value (" + option->value + ")");
    if (value.size() > Config::kMaxValueBytes)
      usage("--" + option->name + ": value too long (at most " +
            std::to_string(Config::kMaxValueBytes) + " characters)");
    parsed.options_.emplace_back(option->name, value);
  }
  const int count = static_cast<int>(parsed.positional.size());
  if (count < command.min_positionals ||
      (command.max_positionals >= 0 && count > command.max_positionals)) {
    std::string expected = command.positionals.empty() ? "no arguments" : command.positionals;
    usage("expected " + expected + ", got " + std::to_string(count) + " argument" +
          (count == 1 ? "" : "s"));
  }
  return parsed;
}

bool Arguments::has(const std::string& option) const {
  return std::any_of(options_.begin(), options_.end(),
                     [&](const auto& entry) { return entry.first == option; });
}

std::string Arguments::value(const std::string& option, const std::string& fallback) const {
  for (const auto& [name, text] : options_) {
    if (name == option) return text;
  }
  return fallback;
}

std::vector<std::string> Arguments::values(const std::string& option) const {
  std::vector<std::string> found;
  for (const auto& [name, text] : options_) {
    if (name == option) found.push_back(text);
  }
  return found;
}

std::optional<int64_t> Arguments::optional_integer(const std::string& option, int64_t min,
                                                   int64_t max) const {
  if (!has(option)) return std::nullopt;
  const std::string value = this->value(option);
  int64_t number = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
  if (error != std::errc() || end != value.data() + value.size() || number < min || number > max) {
    usage("--" + option + " expects " + range_text(min, max) + ", got '" + shown(value) + "'");
  }
  return number;
}

int64_t Arguments::integer(const std::string& option, int64_t fallback, int64_t min,
                           int64_t max) const {
  return optional_integer(option, min, max).value_or(fallback);
}

uint64_t Arguments::unsigned_integer(const std::string& option, uint64_t fallback) const {
  if (!has(option)) return fallback;
  const std::string value = this->value(option);
  uint64_t number = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
  if (error != std::errc() || end != value.data() + value.size()) {
    usage("--" + option + " expects a whole number from 0 to 2^64-1, got '" + shown(value) + "'");
  }
  return number;
}

namespace {

double parse_number(const std::string& option, const std::string& value, double min, double max) {
  char* end = nullptr;
  const double number = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(number) ||
      number < min || number > max) {
    usage("--" + option + " expects a number from " + std::to_string(min) + " to " +
          std::to_string(max) + ", got '" + shown(value) + "'");
  }
  return number;
}

}  // namespace

double Arguments::number(const std::string& option, double fallback, double min, double max) const {
  return has(option) ? parse_number(option, value(option), min, max) : fallback;
}

std::vector<double> Arguments::numbers(const std::string& option, double min, double max) const {
  std::vector<double> values;
  if (!has(option)) return values;
  const std::string list = value(option);
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    values.push_back(parse_number(option, list.substr(start, comma - start), min, max));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

void Arguments::exclusive(const std::string& first, const std::string& second) const {
  if (has(first) && has(second)) usage("--" + first + " and --" + second + " exclude each other");
}

Config Arguments::load_config(std::string_view kind) const {
  Config config = Config::load_file(positional.at(0));
  expect_kind(config, kind);
  for (const auto& [key, text] : overrides) config.set(key, text);
  return config;
}

}  // namespace tendril::apps
