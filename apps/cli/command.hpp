#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cli/arguments.hpp"

namespace tendril::apps {

// One option of a command: `--name VALUE` (or `--name=VALUE`, or `-s VALUE` with a short name),
// or a switch `--name` when `value` is empty.
struct OptionSpec {
  std::string name;         // without dashes: "episodes"
  std::string value;        // what the value is, in capitals ("N", "FILE.csv"); "" for a switch
  std::string help;         // one sentence or two; the default is said here
  char short_name = '\0';   // 'o' for -o
  bool repeatable = false;  // may be given more than once (values collected in order)
};

// One command of the program: its words (`{"model", "fit"}`), what it takes and does, and the
// function that runs it. `tendril <words> --help`, `tendril help <words>`, the parser and the
// reference page (docs/cli.md) all read this one table, so they cannot disagree.
struct CommandSpec {
  std::vector<std::string> words;
  std::string positionals;  // the usage of the positional arguments: "EXPERIMENT.yaml"
  int min_positionals = 0;
  int max_positionals = 0;  // -1: any number
  std::string summary;      // one line for the command list
  std::string description;  // paragraphs for --help (blank-line separated)
  std::vector<OptionSpec> options;
  // `--set key=value` changes the command's YAML file (or the run's experiment); commands
  // without one refuse it with an error rather than ignore it.
  bool takes_set = false;
  std::string set_help;  // what --set changes, when takes_set
  std::vector<std::string> examples;
  // The arguments go to the command unparsed, --help included (`plot`, whose options the
  // plotting package parses).
  bool passthrough = false;
  std::function<int(const Arguments&)> run;

  std::string name() const;  // the words joined by spaces
};

// The commands of this build, in the order `tendril help` lists them.
std::vector<CommandSpec> command_table();

// Runs the program: `args` without the program name. Returns the exit status (0 done, 1 an error,
// 2 a usage error: unknown command or option, wrong arguments).
int run_command_line(const std::vector<CommandSpec>& table, const std::vector<std::string>& args);

// The help of one command (what `--help` prints) and the list of all (what `tendril help`
// prints).
std::string command_help(const CommandSpec& command);
std::string program_help(const std::vector<CommandSpec>& table);
// docs/cli.md: every command's help as Markdown.
std::string command_reference_markdown(const std::vector<CommandSpec>& table);

}  // namespace tendril::apps
