#include "cli/command.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <sstream>

#include "cli/suggestion.hpp"
#include "tendril/core/error.hpp"

namespace tendril::apps {

namespace {

constexpr std::size_t kWidth = 100;

// `text` wrapped at kWidth columns with `indent` spaces before each line; blank lines (paragraph
// breaks) kept; lines starting with spaces (examples, lists) kept as they are.
std::string wrapped(const std::string& text, std::size_t indent) {
  std::string out;
  std::istringstream lines(text);
  std::string line;
  const std::string pad(indent, ' ');
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == ' ') {
      out += line.empty() ? "\n" : pad + line + "\n";
      continue;
    }
    std::istringstream words(line);
    std::string word, current;
    while (words >> word) {
      if (!current.empty() && indent + current.size() + 1 + word.size() > kWidth) {
        out += pad + current + "\n";
        current.clear();
      }
      current += (current.empty() ? "" : " ") + word;
    }
    if (!current.empty()) out += pad + current + "\n";
  }
  return out;
}

std::string option_usage(const OptionSpec& option) {
  std::string text = option.short_name ? std::string("-") + option.short_name + ", " : "";
  text += "--" + option.name;
  if (!option.value.empty()) text += " " + option.value;
  return text;
}

std::string usage_line(const CommandSpec& command) {
  std::string text = "tendril " + command.name();
  if (!command.positionals.empty()) text += " " + command.positionals;
  if (command.takes_set) text += " [--set KEY=VALUE ...]";
  if (!command.options.empty()) text += " [options]";
  return text;
}

// The commands whose words start with `prefix`.
std::vector<const CommandSpec*> under(const std::vector<CommandSpec>& table,
                                      const std::vector<std::string>& prefix) {
  std::vector<const CommandSpec*> found;
  for (const CommandSpec& command : table) {
    if (command.words.size() >= prefix.size() &&
        std::equal(prefix.begin(), prefix.end(), command.words.begin())) {
      found.push_back(&command);
    }
  }
  return found;
}

// The command named by the longest run of leading words of `args`, and how many words it took.
const CommandSpec* match(const std::vector<CommandSpec>& table,
                         const std::vector<std::string>& args, std::size_t& taken) {
  const CommandSpec* best = nullptr;
  for (const CommandSpec& command : table) {
    if (command.words.size() <= args.size() &&
        std::equal(command.words.begin(), command.words.end(), args.begin()) &&
        (best == nullptr || command.words.size() > best->words.size())) {
      best = &command;
    }
  }
  taken = best ? best->words.size() : 0;
  return best;
}

bool asks_for_help(const std::vector<std::string>& args) {
  for (const std::string& arg : args) {
    if (arg == "--") return false;
    if (arg == "--help" || arg == "-h") return true;
  }
  return false;
}

// The commands of a group word ("model"), one per line with its summary.
std::string group_help(const std::vector<const CommandSpec*>& group) {
  std::string text;
  for (const CommandSpec* member : group) {
    text += "  tendril " + member->name() + "\n" + wrapped(member->summary, 6);
  }
  return text;
}

int unknown_command(const std::vector<CommandSpec>& table, const std::vector<std::string>& args) {
  // A group word alone ("model") or with an unknown verb ("model fir").
  const std::vector<const CommandSpec*> group = under(table, {args[0]});
  if (!group.empty()) {
    std::vector<std::string> verbs;
    for (const CommandSpec* command : group) verbs.push_back(command->words.at(1));
    std::string list;
    for (const std::string& verb : verbs) list += (list.empty() ? "" : ", ") + verb;
    if (args.size() == 1) {
      std::fprintf(stderr, "tendril %s: needs one of: %s (tendril help %s)\n", args[0].c_str(),
                   list.c_str(), args[0].c_str());
    } else {
      const std::string close = closest(args[1], verbs);
      std::fprintf(stderr, "tendril %s: unknown command '%s'%s; expected one of: %s\n",
                   args[0].c_str(), args[1].c_str(),
                   close.empty() ? "" : (" (did you mean '" + close + "'?)").c_str(), list.c_str());
    }
    return 2;
  }
  std::vector<std::string> names;
  for (const CommandSpec& command : table) names.push_back(command.words.front());
  const std::string close = closest(args[0], names);
  std::fprintf(stderr, "tendril: unknown command '%s'%s; `tendril help` lists the commands\n",
               args[0].c_str(), close.empty() ? "" : (" (did you mean '" + close + "'?)").c_str());
  return 2;
}

}  // namespace

std::string CommandSpec::name() const {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

std::string command_help(const CommandSpec& command) {
  std::string text = "usage: " + usage_line(command) + "\n\n" + wrapped(command.summary, 0);
  if (!command.description.empty()) text += "\n" + wrapped(command.description, 0);
  if (!command.options.empty() || command.takes_set) {
    text += "\noptions:\n";
    std::vector<std::pair<std::string, std::string>> rows;
    if (command.takes_set) rows.emplace_back("--set KEY=VALUE", command.set_help);
    for (const OptionSpec& option : command.options) {
      rows.emplace_back(option_usage(option), option.help);
    }
    rows.emplace_back("-h, --help", "Show this help.");
    for (const auto& [usage, help] : rows) {
      text += "  " + usage + "\n" + wrapped(help, 6);
    }
  }
  if (!command.examples.empty()) {
    text += "\nexamples:\n";
    for (const std::string& example : command.examples) text += "  " + example + "\n";
  }
  return text;
}

std::string program_help(const std::vector<CommandSpec>& table) {
  std::string text =
      "usage: tendril <command> [arguments]    (tendril <command> --help for its options)\n\n"
      "tendril simulates soft robots, trains controllers for them, learns models of them,\n"
      "keeps them safe and adapts controllers to the real robot.\n\ncommands:\n";
  std::size_t width = 0;
  for (const CommandSpec& command : table) width = std::max(width, command.name().size());
  for (const CommandSpec& command : table) {
    const std::string name = command.name();
    // The summary wrapped beside the names.
    const std::string summary = wrapped(command.summary, width + 4);
    text += "  " + name + (summary.empty() ? "\n" : summary.substr(2 + name.size()));
  }
  text += "\n  --version" + std::string(std::max<std::size_t>(width, 9) - 7, ' ') +
          "The version, and how floating-point results reproduce (docs/reproducibility.md)\n";
  return text;
}

std::string command_reference_markdown(const std::vector<CommandSpec>& table) {
  std::string text =
      "# Command-line reference\n\n"
      "Generated from the program's command table (`tendril help --markdown`); every command\n"
      "also prints its part with `--help`.\n\n| command | what it does |\n|---|---|\n";
  for (const CommandSpec& command : table) {
    text += "| [`" + command.name() + "`](#tendril-";
    for (const std::string& word : command.words) text += word + "-";
    text.pop_back();
    text += ") | " + command.summary + " |\n";
  }
  for (const CommandSpec& command : table) {
    text += "\n## tendril " + command.name() + "\n\n```text\n" + command_help(command) + "```\n";
  }
  return text;
}

int run_command_line(const std::vector<CommandSpec>& table, const std::vector<std::string>& args) {
  if (args.empty()) {
    std::fputs(program_help(table).c_str(), stderr);
    return 2;
  }
  if (args[0] == "--help" || args[0] == "-h" || (args[0] == "help" && args.size() == 1)) {
    std::fputs(program_help(table).c_str(), stdout);
    return 0;
  }
  if (args[0] == "help") {
    if (args.size() == 2 && args[1] == "--markdown") {
      std::fputs(command_reference_markdown(table).c_str(), stdout);
      return 0;
    }
    const std::vector<std::string> words(args.begin() + 1, args.end());
    std::size_t taken = 0;
    const CommandSpec* command = match(table, words, taken);
    const std::vector<const CommandSpec*> group = under(table, words);
    if ((command == nullptr || taken != words.size()) && !group.empty()) {
      std::fputs(group_help(group).c_str(), stdout);
      return 0;
    }
    if (command == nullptr || taken != words.size()) return unknown_command(table, words);
    std::fputs(command_help(*command).c_str(), stdout);
    return 0;
  }
  std::size_t taken = 0;
  const CommandSpec* command = match(table, args, taken);
  if (command == nullptr) {
    // "tendril model --help": the group's commands, as `tendril help model` prints them.
    const std::vector<const CommandSpec*> group = under(table, {args[0]});
    if (args.size() == 2 && (args[1] == "--help" || args[1] == "-h") && !group.empty()) {
      std::fputs(group_help(group).c_str(), stdout);
      return 0;
    }
    return unknown_command(table, args);
  }
  const std::vector<std::string> rest(args.begin() + static_cast<std::ptrdiff_t>(taken),
                                      args.end());
  if (!command->passthrough && asks_for_help(rest)) {
    std::fputs(command_help(*command).c_str(), stdout);
    return 0;
  }
  const std::string name = command->name();
  try {
    return command->run(Arguments::parse(*command, rest));
  } catch (const UsageError& e) {
    std::fprintf(stderr, "tendril %s: %s\n(tendril %s --help shows the usage)\n", name.c_str(),
                 e.what(), name.c_str());
    return 2;
  } catch (const Error& e) {
    std::fprintf(stderr, "tendril %s: error: %s\n", name.c_str(), e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "tendril %s: error: out of memory\n", name.c_str());
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "tendril %s: error: %s\n", name.c_str(), e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tendril %s: unexpected error: %s\n", name.c_str(), e.what());
    return 1;
  }
}

}  // namespace tendril::apps
