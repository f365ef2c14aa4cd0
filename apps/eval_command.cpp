// `tendril eval`: evaluate a run's model on its environment.
#include <cstdio>
#include <filesystem>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "run_policy.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/evaluation.hpp"

namespace tendril::apps {

int eval_command(const std::vector<std::string>& args) {
  const CommandLine line =
      CommandLine::parse(args, {"episodes", "seed"}, {"deterministic", "best"});
  require(line.positional.size() == 1, "expected one run directory", "command line");
  const std::filesystem::path run = line.positional.front();
  const int episodes = static_cast<int>(line.integer("episodes", 10, 1, 1000000));
  const uint64_t seed = line.unsigned_integer("seed", 0);

  const bool deterministic = line.has("deterministic");
  const RunPolicy policy = open_run_policy(run, line.has("best"));
  const rl::EvaluationResult result =
      rl::evaluate_policy(*policy.policy, *policy.env, episodes, deterministic, seed);
  std::printf("%s on %s, %d episodes (%s): mean return %.3f +/- %.3f\n",
              policy.source.string().c_str(), policy.experiment.env.id.c_str(), episodes,
              deterministic ? "deterministic" : "stochastic", result.mean_return(),
              result.std_return());
  for (std::size_t i = 0; i < result.returns.size(); ++i) {
    std::printf("  episode %2zu: return %10.3f  length %lld\n", i, result.returns[i],
                static_cast<long long>(result.lengths[i]));
  }
  return 0;
}

}  // namespace tendril::apps
