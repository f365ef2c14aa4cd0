#include "run_policy.hpp"

#include <cstdio>

#include "tendril/core/error.hpp"
#include "tendril/core/run_record.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/rl/vec_env_factory.hpp"
#ifdef TENDRIL_WITH_SAFETY
#include "tendril/safety/safety_evaluation.hpp"
#endif

namespace tendril::apps {

namespace fs = std::filesystem;

RunPolicy open_run_policy(const fs::path& run, bool best,
                          const std::vector<std::pair<std::string, std::string>>& overrides) {
#ifdef TENDRIL_WITH_SAFETY
  // A safety co-training or constrained run: its task experiment (what its model.policy acts in).
  Config config = load_run_config(run);
  const bool safety_run = config.has("safety") || config.has("constrained");
  for (const auto& [key, value] : overrides) config.set(key, value);
  RunPolicy result{safety_run ? safety::task_experiment_of_config(config)
                              : rl::load_run_experiment(run, overrides),
                   {},
                   {},
                   {},
                   {}};
#else
  RunPolicy result{rl::load_run_experiment(run, overrides), {}, {}, {}, {}};
#endif
  const rl::Experiment& experiment = result.experiment;
  const fs::path file = run / (best ? "best_model.policy" : "model.policy");
  require(!best || fs::exists(file), "no best_model.policy (the run's eval.save_best is off)",
          run.string());
  if (fs::exists(file)) {
    result.source = file;
    result.policy = rl::load_policy(file);
    result.env = rl::make_env(experiment.env);
    return result;
  }
  std::vector<std::string> skipped;
  result.source = rl::newest_intact_checkpoint(run, &skipped);
  for (const std::string& reason : skipped) {
    std::fprintf(stderr, "skipped %s; using %s\n", reason.c_str(), result.source.c_str());
  }
  std::shared_ptr<envs::VecEnv> training_env = rl::make_vec_env(experiment.env);
  std::shared_ptr<rl::Algorithm> algorithm = rl::make_algorithm(experiment, *training_env);
  algorithm->load(result.source);
  result.env = rl::make_evaluation_env(experiment.env, *training_env);
  result.policy = std::shared_ptr<const rl::Policy>(algorithm, &algorithm->policy());
  result.keep_alive = training_env;
  return result;
}

}  // namespace tendril::apps
