#include "tendril/safety/diamond_deployment.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/core/policy.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/runner/policy_runner.hpp"
#include "tendril/envs/sma_limb/learned_safety_env.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_evaluation.hpp"

namespace tendril::safety {

using envs::sma_limb::LearnedSafetyEnv;

namespace {

// The diamond's nominal moves through the filter, as a policy on the robot's readings
// [θx, θy, t_s] (SmaLimb/Robot-v0): x = [θx, θy, θ̇x, θ̇y, t/T], θ̇ the finite difference of the
// last two readings and t the steps since the start; where Q_s(x, u_nominal) ≤ ε₂ the critic's
// greedy move replaces the nominal one (eq. 6.5). It keeps its last decision for the trace.
class FilteredDiamond final : public Policy {
 public:
  struct Decision {
    double elapsed_s = 0.0;
    double value = 0.0;
    bool intervened = false;
    int move = 0;
  };

  FilteredDiamond(const Env& limb, const SafetyCritic& critic, const LearnedSafetyEnv::Params& task,
                  double epsilon)
      : observations_(limb.observation_space()),
        actions_(limb.action_space()),
        critic_(critic),
        task_(task),
        epsilon_(epsilon) {}

  const Space& observation_space() const override { return observations_; }
  const Space& action_space() const override { return actions_; }

  void begin_episode(const Observation& reading) const override {
    start_s_ = previous_s_ = reading[2];
    previous_angles_ = Eigen::Vector2d(reading[0], reading[1]);
    velocity_.setZero();
    steps_ = 0;
  }

  Action act(const Observation& reading, bool /*deterministic*/, Rng& /*rng*/) const override {
    const Eigen::Vector2d angles(reading[0], reading[1]);
    if (steps_ > 0) {
      const double dt = reading[2] - previous_s_;
      if (dt > 0.0) velocity_ = (angles - previous_angles_) / dt;
      previous_angles_ = angles;
      previous_s_ = reading[2];
    }
    decision_.elapsed_s = reading[2] - start_s_;
    const int nominal = diamond_move(decision_.elapsed_s);
    require(nominal >= 0, "the diamond is over", "run_diamond");
    Observation x(5);
    x << angles.cast<float>(), velocity_.cast<float>(),
        static_cast<float>(std::min<double>(1.0, static_cast<double>(steps_) / task_.horizon));
    decision_.value = critic_.value(x, Action::Constant(1, static_cast<float>(nominal)));
    decision_.intervened = decision_.value <= epsilon_;
    decision_.move = decision_.intervened ? static_cast<int>(critic_.safe_action(x)[0]) : nominal;
    ++steps_;
    return LearnedSafetyEnv::throttles(decision_.move).cast<float>();
  }

  const Decision& last_decision() const { return decision_; }

 private:
  const Space& observations_;
  const Space& actions_;
  const SafetyCritic& critic_;
  LearnedSafetyEnv::Params task_;
  double epsilon_;
  mutable double start_s_ = 0.0, previous_s_ = 0.0;
  mutable Eigen::Vector2d previous_angles_ = Eigen::Vector2d::Zero();
  mutable Eigen::Vector2d velocity_ = Eigen::Vector2d::Zero();
  mutable int64_t steps_ = 0;
  mutable Decision decision_;
};

// One trial's trace: a row per reading the policy acted on, the first reading outside the safe
// circle, and the end of the sequence (the run stops after the step whose reading is past it).
class DiamondTrace final : public envs::RunObserver {
 public:
  DiamondTrace(const FilteredDiamond& policy, const LearnedSafetyEnv::Params& task,
               DiamondTrial& trial)
      : policy_(policy), task_(task), trial_(trial) {}

  void on_episode_start(int64_t /*episode*/, uint64_t /*seed*/, const Observation& reading,
                        const Env& /*env*/) override {
    start_s_ = reading[2];
    check(reading);
  }

  void on_step(const envs::StepView& step) override {
    require(!step.result.terminated, "the twin's state became non-finite", "run_diamond");
    const FilteredDiamond::Decision& decision = policy_.last_decision();
    const Eigen::Vector2d throttles = LearnedSafetyEnv::throttles(decision.move);
    Eigen::Matrix<double, 7, 1> row;
    row << decision.elapsed_s, step.observation[0], step.observation[1], decision.value,
        decision.intervened ? 1.0 : 0.0, throttles[0], throttles[1];
    rows.push_back(row);
    interventions += decision.intervened ? 1 : 0;
    check(step.result.observation);
  }

  bool over() const { return over_; }

  std::vector<Eigen::Matrix<double, 7, 1>> rows;
  int64_t interventions = 0;

 private:
  void check(const Observation& reading) {
    const double elapsed = reading[2] - start_s_;
    if (std::isnan(trial_.time_to_violation_s) &&
        LearnedSafetyEnv::safety_margin(task_, reading[0], reading[1]) <= 0.0) {
      trial_.time_to_violation_s = elapsed;
    }
    over_ = diamond_move(elapsed) < 0;
  }

  const FilteredDiamond& policy_;
  LearnedSafetyEnv::Params task_;
  DiamondTrial& trial_;
  double start_s_ = 0.0;
  bool over_ = false;
};

}  // namespace

int diamond_move(double seconds) {
  // (move, seconds): u1 3 s, u4 3 s, u3 6 s, u2 12 s, u1 6 s, u3 3 s; moves 0–3 are u1–u4.
  static const std::pair<int, double> segments[] = {{0, 3.0},  {3, 3.0}, {2, 6.0},
                                                    {1, 12.0}, {0, 6.0}, {2, 3.0}};
  double end = 0.0;
  for (const auto& [move, duration] : segments) {
    end += duration;
    if (seconds < end) return move;
  }
  return -1;
}

DiamondTrial run_diamond_trial(Env& limb, const SafetyCritic& critic,
                               const LearnedSafetyEnv::Params& task, double epsilon,
                               uint64_t seed) {
  DiamondTrial trial;
  trial.epsilon = epsilon;
  trial.time_to_violation_s = std::numeric_limits<double>::quiet_NaN();
  const FilteredDiamond policy(limb, critic, task, epsilon);
  DiamondTrace trace(policy, task, trial);
  // One episode, until the reading that ends the 33 s sequence.
  envs::RunSettings settings;
  settings.episodes = 1;
  settings.seed = seed;
  settings.stop_requested = [&trace] { return trace.over(); };
  const envs::RunResult result = envs::run_policy(policy, limb, settings, {&trace});
  trial.intervention_rate = result.steps == 0 ? 0.0
                                              : static_cast<double>(trace.interventions) /
                                                    static_cast<double>(result.steps);
  trial.trajectory.resize(static_cast<Eigen::Index>(trace.rows.size()), 7);
  for (std::size_t i = 0; i < trace.rows.size(); ++i) {
    trial.trajectory.row(static_cast<Eigen::Index>(i)) = trace.rows[i].transpose();
  }
  return trial;
}

std::vector<DiamondTrial> run_diamond(const std::filesystem::path& critic_run,
                                      const DiamondOptions& options) {
  require(options.trials >= 1 && !options.epsilons.empty(), "at least one trial and one ε₂ value",
          "run_diamond");
  const rl::Experiment run = task_experiment_of_run(critic_run);
  auto model_env = envs::make(run.env.id, run.env.params);
  const auto* limb_task = envs::find_wrapper<LearnedSafetyEnv>(*model_env);
  require(limb_task != nullptr, "the critic's run is not on " + std::string(LearnedSafetyEnv::kId),
          critic_run.string());
  const LearnedSafetyEnv::Params task = limb_task->params();
  const auto critic = load_safety_critic(critic_run / "safety.critic");

  std::vector<DiamondTrial> trials;
  for (double epsilon : options.epsilons) {
    for (int k = 0; k < options.trials; ++k) {
      auto limb = envs::make("SmaLimb/Robot-v0", options.limb_params);
      DiamondTrial trial =
          run_diamond_trial(*limb, *critic, task, epsilon, options.seed + static_cast<uint64_t>(k));
      trial.trial = k;
      trials.push_back(std::move(trial));
    }
  }
  return trials;
}

}  // namespace tendril::safety
