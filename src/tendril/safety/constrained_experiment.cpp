#include "tendril/safety/constrained_experiment.hpp"

#include <memory>
#include <optional>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"

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

namespace {

class ConstrainedBaseline : public rl::RunCompanion {
 public:
  explicit ConstrainedBaseline(const ConstrainedExperiment& experiment) : experiment_(experiment) {}

  std::string name() const override { return experiment_.method + " baseline"; }

  void bind(rl::Algorithm& algorithm) override {
    auto& sac = dynamic_cast<rl::Sac&>(algorithm);
    cost_critic_.emplace(sac.policy(), experiment_.cost_critic, experiment_.task.seed + 1);
    penalty_.emplace(*cost_critic_, experiment_.cost_limit, experiment_.multiplier,
                     experiment_.task.n_timesteps);
    sac.set_actor_penalty(&*penalty_);
  }
  void unbind(rl::Algorithm& algorithm) override {
    dynamic_cast<rl::Sac&>(algorithm).set_actor_penalty(nullptr);
  }

  void on_step(const rl::StepEvent& event) override {
    cost_critic_->on_step(event);
    penalty_->on_step(event);
  }
  void add_scalars(rl::TrainStats& stats) override {
    stats.emplace_back("lagrangian/multiplier", penalty_->multiplier());
    stats.emplace_back("lagrangian/cost_value", penalty_->last_cost_value());
    stats.emplace_back("lagrangian/cost_critic_loss", cost_critic_->last_loss());
  }

  void save(ArchiveWriter& writer) const override {
    cost_critic_->save(writer, "constrained/cost_critic/");
    penalty_->save(writer, "constrained/penalty/");
  }
  std::function<void()> load(const ArchiveReader& reader) override {
    std::function<void()> install_critic =
        cost_critic_->prepare_load(reader, "constrained/cost_critic/");
    std::function<void()> install_penalty = penalty_->prepare_load(reader, "constrained/penalty/");
    return [install_critic, install_penalty] {
      install_critic();
      install_penalty();
    };
  }

 private:
  const ConstrainedExperiment& experiment_;
  std::optional<CostCritic> cost_critic_;
  std::optional<LagrangianPenalty> penalty_;
};

}  // namespace

rl::CompanionFactory constrained_baseline(const ConstrainedExperiment& experiment) {
  return [&experiment] { return std::make_unique<ConstrainedBaseline>(experiment); };
}

rl::TrainResult train_constrained(const ConstrainedExperiment& experiment,
                                  const std::filesystem::path& run_directory,
                                  rl::TrainOptions options) {
  options.companion = constrained_baseline(experiment);
  return rl::train(experiment.task, run_directory, options);
}

}  // namespace tendril::safety
