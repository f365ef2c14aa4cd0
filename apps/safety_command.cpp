// `tendril safety`: train a task agent with a co-trained safety agent, and evaluate the run
// with and without the safety filter (seed 001 ch. 6).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/safety/safety_experiment.hpp"

namespace tendril::apps {
namespace {

std::filesystem::path new_run_directory(const std::string& output) {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  return output + "-" + stamp;
}

void print_evaluation(const char* name, const safety::SafetyEvaluation& e) {
  std::printf("%-10s return %9.3f +/- %8.3f   safety rate %.3f   interventions %.3f\n", name,
              e.mean_return, e.std_return, e.safety_rate, e.intervention_rate);
}

int evaluate(const std::filesystem::path& run, double epsilon, int episodes, uint64_t seed) {
  const safety::RunSafetyEvaluation result =
      safety::evaluate_safety_run(run, epsilon, episodes, seed);
  std::printf("%d episodes (reset seeds %llu, ...), epsilon_2 = %g\n", episodes,
              static_cast<unsigned long long>(seed), epsilon);
  print_evaluation("task", result.unfiltered);
  if (result.filtered) print_evaluation("filtered", *result.filtered);
  return 0;
}

double parse_epsilon(const CommandLine& line, double fallback) {
  if (!line.has("epsilon")) return fallback;
  const std::string text = line.value("epsilon", "");
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  require(!text.empty() && end == text.c_str() + text.size() && std::isfinite(value),
          "not a finite number: '" + text + "'", "--epsilon");
  return value;
}

}  // namespace

int safety_command(const std::vector<std::string>& args) {
  require(!args.empty() && (args[0] == "train" || args[0] == "eval"),
          "usage: tendril safety train <experiment.yaml> | eval <run-dir>", "command line");
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "train") {
    const CommandLine line = CommandLine::parse(rest, {"out"}, {});
    const safety::SafetyExperiment experiment =
        safety::SafetyExperiment::from_config(line.load_config());
    const std::filesystem::path run = line.has("out") ? std::filesystem::path(line.value("out", ""))
                                                      : new_run_directory(experiment.task.output);
    std::printf("training %s with a %s safety agent on %s for %lld steps, seed %llu -> %s\n",
                experiment.task.algorithm.c_str(), experiment.safety_algorithm.c_str(),
                experiment.task.env.id.c_str(), static_cast<long long>(experiment.task.n_timesteps),
                static_cast<unsigned long long>(experiment.task.seed), run.string().c_str());
    const safety::SafetyTrainResult result = safety::train_with_safety(experiment, run);
    std::printf("trained in %.1f s; safety buffer: %lld stored, %lld gated, %lld unsafe entries\n",
                result.seconds, static_cast<long long>(result.stored_transitions),
                static_cast<long long>(result.gated_transitions),
                static_cast<long long>(result.unsafe_entries));
    std::printf("model: %s/model.policy  safety critic: %s/safety.critic\n", run.string().c_str(),
                run.string().c_str());
    return evaluate(run, experiment.eval_epsilon, experiment.eval_episodes, experiment.task.seed);
  }
  const CommandLine line = CommandLine::parse(rest, {"epsilon", "episodes", "seed"}, {});
  require(line.positional.size() == 1 && line.overrides.empty(),
          "usage: tendril safety eval <run-dir> [--epsilon E] [--episodes N] [--seed S]",
          "command line");
  const std::filesystem::path run = line.positional[0];
  // A run of `safety train` brings its evaluation settings; any other run is judged unfiltered.
  int default_episodes = 100;
  double default_epsilon = 0.0;
  uint64_t default_seed = 0;
  if (std::filesystem::exists(run / "safety.critic")) {
    const safety::SafetyExperiment experiment =
        safety::SafetyExperiment::from_config(Config::load_file(run / "config.yaml"));
    default_episodes = experiment.eval_episodes;
    default_epsilon = experiment.eval_epsilon;
    default_seed = experiment.task.seed;
  } else {
    default_seed = rl::load_run_experiment(run).seed;
  }
  const int episodes = static_cast<int>(
      line.integer("episodes", default_episodes, 1, std::numeric_limits<int>::max()));
  return evaluate(run, parse_epsilon(line, default_epsilon), episodes,
                  line.unsigned_integer("seed", default_seed));
}

}  // namespace tendril::apps
