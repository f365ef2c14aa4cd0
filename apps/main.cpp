// tendril — simulate soft robots, train and evaluate controllers for them.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "tendril/core/error.hpp"

namespace {

constexpr const char* kUsage = R"(usage: tendril <command> [arguments]

commands:
  simulate <experiment.yaml> [--set key=value ...] [--out DIR]
      Simulate a Cosserat-rod arm under a spline muscle couple; write its tip trajectory
      (tip.csv) and final shape (nodes.csv) to DIR, and print what happened.
  help
      Show this text.
)";

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (args[0] == "simulate") return tendril::apps::simulate_command(rest);
    std::fprintf(stderr, "tendril: unknown command '%s'\n\n%s", args[0].c_str(), kUsage);
    return 2;
  } catch (const tendril::Error& e) {
    std::fprintf(stderr, "tendril %s: error: %s\n", args[0].c_str(), e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tendril %s: unexpected error: %s\n", args[0].c_str(), e.what());
    return 1;
  }
}
