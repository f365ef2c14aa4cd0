#include "cli/arguments.hpp"

#include <gtest/gtest.h>

#include "cli/command.hpp"

namespace tendril::apps {
namespace {

CommandSpec spec(bool takes_set = true) {
  CommandSpec command;
  command.words = {"run"};
  command.summary = "Runs a policy.";
  command.positionals = "RUN";
  command.min_positionals = 1;
  command.max_positionals = 1;
  command.options = {{"episodes", "N", "episodes"},
                     {"stochastic", "", "sample"},
                     {"output", "PATH", "where", 'o'},
                     {"tag", "T", "tags", '\0', true}};
  command.takes_set = takes_set;
  return command;
}

std::string usage_error(const CommandSpec& command, const std::vector<std::string>& args) {
  try {
    Arguments::parse(command, args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Arguments, ReadsPositionalsOptionsSwitchesAndOverrides) {
  const Arguments a = Arguments::parse(
      spec(), {"runs/x", "--episodes=7", "--stochastic", "-o", "out.csv", "--set", "seed=3",
               "--tag", "a", "--tag", "b", "--set=env.params.g=20"});
  EXPECT_EQ(a.positional, std::vector<std::string>{"runs/x"});
  EXPECT_EQ(a.integer("episodes", 10, 1, 100), 7);
  EXPECT_TRUE(a.has("stochastic"));
  EXPECT_EQ(a.value("output"), "out.csv");
  EXPECT_EQ(a.values("tag"), (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(a.overrides.size(), 2u);
  EXPECT_EQ(a.overrides[1].first, "env.params.g");
  EXPECT_EQ(a.overrides[1].second, "20");
  // "--" ends the options: a file named like one.
  EXPECT_EQ(Arguments::parse(spec(), {"--", "--episodes"}).positional.front(), "--episodes");
}

TEST(Arguments, NumbersAreWholeTextOrRefused) {
  for (const char* bad : {"1e9", "3x", "-1", "1.5", "99999999999999999999"}) {
    const Arguments a = Arguments::parse(spec(), {"r", "--episodes", bad});
    EXPECT_THROW(a.integer("episodes", 10, 1, 1000000), UsageError) << bad;
  }
  const Arguments a = Arguments::parse(spec(), {"r", "--episodes", "1000000"});
  EXPECT_EQ(a.integer("episodes", 10, 1, 1000000), 1000000);
}

TEST(Arguments, RefusesWhatTheCommandDoesNotTake) {
  EXPECT_NE(usage_error(spec(), {"r", "--episdoes", "3"}).find("did you mean --episodes"),
            std::string::npos);
  EXPECT_NE(usage_error(spec(), {"r", "--episodes", "1", "--episodes", "2"}).find("twice"),
            std::string::npos);
  EXPECT_NE(usage_error(spec(), {"r", "--episodes"}).find("needs a value"), std::string::npos);
  EXPECT_NE(usage_error(spec(), {"r", "--stochastic=yes"}).find("takes no value"),
            std::string::npos);
  EXPECT_NE(usage_error(spec(), {}).find("expected RUN"), std::string::npos);
  EXPECT_NE(usage_error(spec(), {"a", "b"}).find("got 2 arguments"), std::string::npos);
  EXPECT_NE(usage_error(spec(), {"r", "--set", "seed"}).find("key=value"), std::string::npos);
  // A command without a YAML file refuses --set rather than ignore it.
  EXPECT_NE(usage_error(spec(false), {"r", "--set", "seed=1"}).find("reads no YAML file"),
            std::string::npos);
}

TEST(CommandLine, HelpAndUsageErrorsComeFromTheTable) {
  const std::vector<CommandSpec> table{spec()};
  const std::string help = command_help(table.front());
  EXPECT_NE(help.find("usage: tendril run RUN [--set KEY=VALUE ...] [options]"), std::string::npos);
  EXPECT_NE(help.find("-o, --output PATH"), std::string::npos);
  EXPECT_NE(program_help(table).find("  run  Runs a policy.\n"), std::string::npos);
  EXPECT_NE(command_reference_markdown(table).find("## tendril run"), std::string::npos);
  // Exit statuses: 0 for help, 2 for a usage error or an unknown command.
  EXPECT_EQ(run_command_line(table, {"run", "--help"}), 0);
  EXPECT_EQ(run_command_line(table, {"run"}), 2);
  EXPECT_EQ(run_command_line(table, {"rnu", "x"}), 2);
  EXPECT_EQ(run_command_line(table, {}), 2);
}

}  // namespace
}  // namespace tendril::apps
