#include "tendril/safety/constrained_experiment.hpp"

#include <chrono>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"
#include "tendril/safety/run_files.hpp"

namespace tendril::safety {

ConstrainedExperiment ConstrainedExperiment::from_config(Config config) {
  ConstrainedExperiment e;
  // The constrained section first: Experiment::from_config rejects keys nobody has read.
  const Config section = config.child("constrained");
  e.method = section.get<std::string>("method");
  e.cost_limit = section.get_or("cost_limit", e.cost_limit);
  require(e.cost_limit >= 0.0 && e.cost_limit <= 1.0,
          "must lie in [0, 1] (Q_risk is a probability)", section.where("cost_limit"));
  e.cost_critic = CostCriticSettings::from_config(section.child("cost_critic"));
  e.multiplier = MultiplierSettings::from_config(e.method, section.child("multiplier"));
  e.task = rl::Experiment::from_config(config);
  require(e.task.algorithm == "sac",
          "the constrained baselines train SAC, not '" + e.task.algorithm + "'",
          config.where("algorithm"));
  require(!e.task.env.normalize_observation && !e.task.env.normalize_reward,
          "the cost critic learns on raw observations and the actor's penalty is on the raw "
          "scale: no normalization",
          config.where("env"));
  auto probe = envs::make(e.task.env.id, e.task.env.params);
  probe->reset(0);
  Action action = Action::Zero(probe->action_space().size());
  const Step step = probe->step(action);
  require(step.info.has(info_keys::kCost), "the environment reports no \"cost\" info",
          config.where("env.id"));
  return e;
}

ConstrainedTrainResult train_constrained(const ConstrainedExperiment& experiment,
                                         const std::filesystem::path& run_directory, bool quiet) {
  start_run_directory(run_directory, experiment.task.config);
  const auto start = std::chrono::steady_clock::now();
  const rl::Experiment& task_experiment = experiment.task;
  auto env = rl::make_vec_env(task_experiment.env);
  auto task = rl::make_algorithm(task_experiment, *env);
  auto& sac = dynamic_cast<rl::Sac&>(*task);
  CostCritic cost_critic(sac.policy(), experiment.cost_critic, task_experiment.seed + 1);
  LagrangianPenalty penalty(cost_critic, experiment.cost_limit, experiment.multiplier,
                            task_experiment.n_timesteps);
  sac.set_actor_penalty(&penalty);
  RunScalarLog log(run_directory, [&](rl::TrainStats& stats) {
    stats.emplace_back("lagrangian/multiplier", penalty.multiplier());
    stats.emplace_back("lagrangian/cost_value", penalty.last_cost_value());
    stats.emplace_back("lagrangian/cost_critic_loss", cost_critic.last_loss());
  });
  rl::ProgressLine progress_line(task_experiment.n_timesteps, 0);
  rl::Observers observers{&cost_critic, &penalty, &log};
  if (!quiet) observers.push_back(&progress_line);
  sac.learn(task_experiment.n_timesteps, observers);
  if (!quiet) progress_line.finish();
  sac.set_actor_penalty(nullptr);
  task->policy().save(run_directory / "model.policy");

  ConstrainedTrainResult result;
  result.run_directory = run_directory;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.final_multiplier = penalty.multiplier();
  result.final_cost_value = penalty.last_cost_value();
  return result;
}

}  // namespace tendril::safety
