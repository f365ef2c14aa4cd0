#include "tendril/safety/diamond_deployment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/learned_safety_env.hpp"
#include "tendril/safety/safety_critic.hpp"

// Seed 001's diamond (thesis §6.5) on the twin through the policy runner: the nominal sequence,
// the critic's input built from the readings, the filter's rule and the end of the sequence.
namespace tendril::safety {
namespace {

using envs::sma_limb::LearnedSafetyEnv;

// A critic scripted in code: one value for every (x, u) and one greedy move; it keeps the
// inputs it was asked about.
class ScriptedCritic final : public SafetyCritic {
 public:
  ScriptedCritic(double value, int safe_move) : value_(value), safe_move_(safe_move) {}
  double value(const Observation& x, const Action& /*u*/) const override {
    seen.push_back(x);
    return value_;
  }
  Action safe_action(const Observation& /*x*/) const override {
    return Action::Constant(1, static_cast<float>(safe_move_));
  }
  mutable std::vector<Observation> seen;

 private:
  double value_;
  int safe_move_;
};

// The stiff twin on its calibration, as `tendril safety diamond` deploys it.
std::unique_ptr<Env> calibrated_twin() {
  Config params;
  params.set("calibration", std::string(TENDRIL_CONFIG_DIR) + "/sma_limb/calibration_stiff.yaml");
  return envs::make("SmaLimb/Robot-v0", params);
}

DiamondTrial trial_on_twin(const SafetyCritic& critic, double epsilon, uint64_t seed) {
  auto limb = calibrated_twin();
  return run_diamond_trial(*limb, critic, LearnedSafetyEnv::Params{}, epsilon, seed);
}

TEST(DiamondDeployment, AnUnfilteredTrialTracesTheSequenceFromTheReadings) {
  const ScriptedCritic critic(0.0, 2);
  const LearnedSafetyEnv::Params task;
  const DiamondTrial trial = trial_on_twin(critic, -1000.0, 3);  // Q_s = 0 > ε₂: never filters
  const Eigen::MatrixXd& rows = trial.trajectory;
  // Readings every 55–75 ms for the 33 s the sequence lasts: one row per step, the last within
  // one reading of the end.
  ASSERT_GT(rows.rows(), 400);
  ASSERT_EQ(critic.seen.size(), static_cast<std::size_t>(rows.rows()));
  EXPECT_EQ(rows(0, 0), 0.0);
  EXPECT_LT(rows(rows.rows() - 1, 0), 33.0);
  EXPECT_GT(rows(rows.rows() - 1, 0), 32.9);
  EXPECT_EQ(trial.intervention_rate, 0.0);
  double violation = std::numeric_limits<double>::quiet_NaN();
  for (Eigen::Index k = 0; k < rows.rows(); ++k) {
    if (k > 0) EXPECT_GT(rows(k, 0), rows(k - 1, 0));
    // The nominal move of the sequence at that time, at full throttle.
    const Eigen::Vector2d throttles = LearnedSafetyEnv::throttles(diamond_move(rows(k, 0)));
    EXPECT_EQ(rows(k, 5), throttles[0]) << k;
    EXPECT_EQ(rows(k, 6), throttles[1]) << k;
    EXPECT_EQ(rows(k, 3), 0.0);
    EXPECT_EQ(rows(k, 4), 0.0);
    // x = [θx, θy, θ̇x, θ̇y, t/T]: θ̇ the difference of the last two readings over their time.
    const Observation& x = critic.seen[static_cast<std::size_t>(k)];
    EXPECT_EQ(x[0], static_cast<float>(rows(k, 1)));
    EXPECT_EQ(x[1], static_cast<float>(rows(k, 2)));
    for (int axis = 0; axis < 2; ++axis) {
      const double rate =
          k == 0 ? 0.0
                 : (rows(k, 1 + axis) - rows(k - 1, 1 + axis)) / (rows(k, 0) - rows(k - 1, 0));
      EXPECT_NEAR(x[2 + axis], rate, 1e-4 * std::max(1.0, std::abs(rate))) << k;
    }
    EXPECT_EQ(x[4], static_cast<float>(std::min(1.0, static_cast<double>(k) / task.horizon)));
    if (std::isnan(violation) &&
        LearnedSafetyEnv::safety_margin(task, rows(k, 1), rows(k, 2)) <= 0) {
      violation = rows(k, 0);
    }
  }
  // The full-throttle diamond leaves the 30° circle (Fig. 6.7's unfiltered limb), and the trial
  // reports the first reading that does.
  ASSERT_FALSE(std::isnan(violation));
  EXPECT_EQ(trial.time_to_violation_s, violation);

  // The same seed repeats the trial exactly.
  const ScriptedCritic again(0.0, 2);
  EXPECT_EQ(trial_on_twin(again, -1000.0, 3).trajectory, rows);
}

TEST(DiamondDeployment, WhereTheValueIsBelowTheThresholdTheCriticsMoveReplacesTheNominal) {
  const ScriptedCritic critic(5.0, 2);  // Q_s = 5 ≤ ε₂ = 10: every move is replaced by u3
  const DiamondTrial trial = trial_on_twin(critic, 10.0, 0);
  ASSERT_GT(trial.trajectory.rows(), 400);
  EXPECT_EQ(trial.intervention_rate, 1.0);
  for (Eigen::Index k = 0; k < trial.trajectory.rows(); ++k) {
    EXPECT_EQ(trial.trajectory(k, 3), 5.0);
    EXPECT_EQ(trial.trajectory(k, 4), 1.0);
    EXPECT_EQ(trial.trajectory(k, 5), -10.0);
    EXPECT_EQ(trial.trajectory(k, 6), -10.0);
  }
  EXPECT_EQ(diamond_move(0.0), 0);
  EXPECT_EQ(diamond_move(3.0), 3);
  EXPECT_EQ(diamond_move(32.99), 2);
  EXPECT_EQ(diamond_move(33.0), -1);
}

}  // namespace
}  // namespace tendril::safety
