#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/pneumatic/linear_arm_model.hpp"
#include "tendril/envs/pneumatic/model_dynamics.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs::pneumatic {
namespace {

// A model that answers step k with the k-th of a recorded list of tips, and keeps the
// pressures (bar) each prediction read in the newest row of its window.
class ScriptedModel : public DynamicsModel {
 public:
  explicit ScriptedModel(std::vector<TipVector> tips) : tips_(std::move(tips)) {}
  int state_dim() const override { return 9; }
  int input_dim() const override { return 9; }
  int window_length() const override { return 3; }
  double sample_period() const override { return 0.1; }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override {
    inputs.push_back(windows.row(0).tail(9).transpose().cast<double>());
    next_states = tips_.at(calls_++).transpose().cast<float>();
  }
  std::vector<ChamberVector> inputs;

 private:
  std::vector<TipVector> tips_;
  std::size_t calls_ = 0;
};

ReachEnv& as_reach(Env& env) { return dynamic_cast<ReachEnv&>(env); }

Action delta_on(int chamber, float value) {
  Action action = Action::Zero(9);
  action[chamber] = value;
  return action;
}

Snapshot snapshot_of(const Env& env) {
  Snapshot snapshot;
  SnapshotWriter writer(snapshot);
  env.save_state(writer);
  return snapshot;
}

void restore(Env& env, const Snapshot& snapshot) {
  SnapshotReader reader(snapshot);
  env.load_state(reader);
}

// The learned-model environment steps the same task as PneumaticArm/Reach-v0: fed, through a
// scripted model, the tips the deterministic twin produced under a sequence of deltas, it gives
// the same rewards (eq. (2) with the −2 step penalty), terminations, observation
// normalisation and info, up to the float precision of a model's output; and the model reads
// the pressures p = 0.75 (a + 1) that the twin was sent.
TEST(LearnedReach, StepsTheTaskAsReachOnTheTwinDoesForTheSameTips) {
  const std::string task = "task: G1\nnormalization: {distance_scale_mm: 250}\n";
  auto twin = ReachEnv::create_on_robot(Config::parse(task + "robot: {stochastic: false}"));
  const Observation twin_start = twin->reset(0);
  const TipVector rest = as_reach(*twin).tips();
  std::vector<Action> actions;
  std::vector<Step> twin_steps;
  std::vector<TipVector> tips;
  std::vector<ChamberVector> pressures;
  // Toward +x (chambers 2 and 3 of each module bend it away from 120° and 240°) until module
  // 3's tip leaves B at x = 90 mm, with a refused step in between.
  for (int t = 0; t < 40; ++t) {
    Action action = Action::Zero(9);
    for (int m = 0; m < 3; ++m) action[3 * m + 1] = action[3 * m + 2] = 0.05f;
    if (t == 5) action[0] = 0.2f * (1.0f + 1e-3f);  // beyond the rate limit: not taken
    actions.push_back(action);
    twin_steps.push_back(twin->step(action));
    tips.push_back(as_reach(*twin).tips());
    pressures.push_back(
        as_reach(*twin).command().unaryExpr([](double a) { return ReachEnv::pressure_of(a); }));
    if (twin_steps.back().terminated) break;
  }
  ASSERT_GT(twin_steps.size(), 5u);

  auto model = std::make_shared<ScriptedModel>(tips);
  const Config params = Config::parse(task);
  ReachEnv learned(ReachEnv::setup_from(params, ReachEnv::kModelId),
                   std::make_unique<ModelDynamics>(model, rest));
  EXPECT_TRUE(learned.reset(0).isApprox(twin_start, 1e-6f));
  for (std::size_t t = 0; t < twin_steps.size(); ++t) {
    const Step step = learned.step(actions[t]);
    const Step& expected = twin_steps[t];
    EXPECT_NEAR(step.reward, expected.reward, 1e-3 * std::max(1.0, std::abs(expected.reward))) << t;
    EXPECT_EQ(step.terminated, expected.terminated) << t;
    EXPECT_TRUE(step.observation.isApprox(expected.observation, 1e-5f)) << t;
    for (const char* key :
         {"is_success", "collision", "warning", "outside_boundary", "rate_limited", "nan"}) {
      EXPECT_EQ(*step.info.get(key), *expected.info.get(key)) << key << " at " << t;
    }
    EXPECT_NEAR(*step.info.get("goal_distance_mm"), *expected.info.get("goal_distance_mm"), 1e-3);
    EXPECT_TRUE(model->inputs[t].isApprox(pressures[t], 1e-6)) << t;
  }
  EXPECT_EQ(*twin_steps[5].info.get("rate_limited"), 1.0);
  EXPECT_TRUE(twin_steps.back().terminated);
  EXPECT_EQ(*twin_steps.back().info.get("outside_boundary"), 1.0);
}

// Without a model the stand-in answers in closed form: vented chambers keep the arm at rest;
// one step of 0.2 on chamber 1 of module 1 (0.15 bar) moves every tip toward −x by
// β kBend span p and down by β kExtension p.
TEST(LearnedReach, TheStandInStartsAtRestAndBendsAwayFromTheChamber) {
  EXPECT_EQ(make(ReachEnv::kModelId)->observation_space().size(), 11);
  auto env = ReachEnv::create_on_model(Config());
  EXPECT_EQ(env->observation_space().size(), 11);
  EXPECT_EQ(env->action_space().describe(), "Box(9, [-0.2, 0.2])");
  env->reset(0);
  ReachEnv& task = as_reach(*env);
  EXPECT_TRUE(task.tips().isApprox(LinearArmModel::rest(), 1e-6));
  env->step(Action::Zero(9));
  EXPECT_TRUE(task.tips().isApprox(LinearArmModel::rest(), 1e-6));
  env->step(delta_on(0, 0.2f));
  const double beta = 1.0 - std::exp(-0.1 / 0.3), p = 0.15;
  for (int m = 0; m < 3; ++m) {
    EXPECT_NEAR(task.tips()[3 * m], -beta * LinearArmModel::kBend * (m + 1) * p, 1e-3) << m;
    EXPECT_NEAR(task.tips()[3 * m + 1], 0.0, 1e-3) << m;
    EXPECT_NEAR(task.tips()[3 * m + 2],
                LinearArmModel::rest()[3 * m + 2] - beta * LinearArmModel::kExtension * p, 1e-3)
        << m;
  }
}

// GPRCA's model (seed 002 §IV-C): predictions from the robot's measured history, which
// follow() advances with measured tips instead of the model's own predictions.
TEST(LearnedReach, TheModelCanFollowMeasuredTips) {
  ModelDynamics model(std::make_shared<LinearArmModel>(), LinearArmModel::rest());
  TipVector measured = LinearArmModel::rest();
  measured[0] += 7.0;
  model.reset_to(measured);
  ChamberVector pressures = ChamberVector::Zero();
  pressures[0] = 1.2;
  const TipVector first = model.predict_next(pressures);
  EXPECT_EQ(model.predict_next(pressures), first);  // the history did not move
  // LinearArmModel's closed form from the measured tips.
  const double beta = 1.0 - std::exp(-LinearArmModel::kPeriod / LinearArmModel::kLag);
  const TipVector expected = measured + beta * (LinearArmModel::steady_state(pressures) - measured);
  EXPECT_LT((first - expected).norm(), 1e-3);  // float model
  TipVector next_measured = first;
  next_measured[1] -= 3.0;
  model.follow(next_measured);
  const TipVector second = model.predict_next(pressures);
  const TipVector expected_second =
      next_measured + beta * (LinearArmModel::steady_state(pressures) - next_measured);
  EXPECT_LT((second - expected_second).norm(), 1e-3);
  EXPECT_THROW(model.follow(TipVector::Constant(NAN)), Error);
}

// rest_jitter_mm: a seeded reset moves the rest by a repeatable draw; without it every episode
// starts at the rest.
TEST(LearnedReach, RestJitterGivesRepeatableStartsPerSeed) {
  const auto jittered = ReachEnv::create_on_model(Config::parse("rest_jitter_mm: 4.0\n"));
  const auto plain = ReachEnv::create_on_model(Config::parse("{}"));
  jittered->reset(3);
  const TipVector first = as_reach(*jittered).tips();
  jittered->reset();
  const TipVector second = as_reach(*jittered).tips();
  jittered->reset(3);
  EXPECT_EQ(as_reach(*jittered).tips(), first);
  EXPECT_NE(first, second);
  plain->reset(3);
  EXPECT_EQ(as_reach(*plain).tips(), LinearArmModel::rest());
  const double shift = (first - LinearArmModel::rest()).norm();
  EXPECT_GT(shift, 1.0);
  EXPECT_LT(shift, 4.0 * 6.0);
  EXPECT_THROW(ReachEnv::create_on_model(Config::parse("rest_jitter_mm: -1\n")), Error);
}

// Without initial_offset_mm (or with 0) the start is the one it was before the key existed:
// the rest, and with rest_jitter_mm the same nine normal draws of the jitter's stream (11) as
// before, so every earlier result repeats bit for bit.
TEST(LearnedReach, NoInitialOffsetKeepsTheEarlierStarts) {
  auto plain = ReachEnv::create_on_model(Config::parse("{}"));
  auto zero = ReachEnv::create_on_model(Config::parse("initial_offset_mm: 0\n"));
  EXPECT_EQ(plain->reset(7), zero->reset(7));
  EXPECT_EQ(as_reach(*zero).tips(), LinearArmModel::rest());
  zero->reset();
  EXPECT_EQ(as_reach(*zero).tips(), LinearArmModel::rest());
  for (int t = 0; t < 20; ++t) {
    const Action action = delta_on((4 * t) % 9, (t % 2 == 0) ? 0.3f : -0.1f);
    EXPECT_EQ(plain->step(action).observation, zero->step(action).observation) << t;
  }
  auto jittered =
      ReachEnv::create_on_model(Config::parse("rest_jitter_mm: 4.0\ninitial_offset_mm: 0\n"));
  jittered->reset(3);
  Rng stream(3, 11);
  TipVector expected = LinearArmModel::rest();
  for (int i = 0; i < 9; ++i) expected[i] += 4.0 * stream.normal();
  EXPECT_EQ(as_reach(*jittered).tips(), expected);
}

// initial_offset_mm: each module's rest tip moves by at most the radius, the same seed gives the
// same start, other seeds other starts, and the draws fill the ball (some come near its edge).
TEST(LearnedReach, InitialOffsetMovesEachTipWithinTheRadiusRepeatablyPerSeed) {
  constexpr double kRadius = 40.0;
  auto env = ReachEnv::create_on_model(Config::parse("initial_offset_mm: 40\n"));
  auto twin = ReachEnv::create_on_model(Config::parse("initial_offset_mm: 40\n"));
  const TipVector rest = LinearArmModel::rest();
  std::vector<TipVector> starts;
  double largest = 0.0, smallest = kRadius;
  for (uint64_t seed = 0; seed < 50; ++seed) {
    EXPECT_EQ(env->reset(seed), twin->reset(seed)) << seed;
    const TipVector start = as_reach(*env).tips();
    for (int module = 0; module < 3; ++module) {
      const double shift = (start - rest).segment<3>(3 * module).norm();
      EXPECT_LE(shift, kRadius) << seed;
      largest = std::max(largest, shift);
      smallest = std::min(smallest, shift);
    }
    for (const TipVector& earlier : starts) EXPECT_NE(start, earlier) << seed;
    starts.push_back(start);
  }
  // 150 uniform draws in the ball: P(all within 0.8 r) = 0.512^150, P(none within 0.5 r) =
  // 0.875^150, both below 1e-8.
  EXPECT_GT(largest, 0.8 * kRadius);
  EXPECT_LT(smallest, 0.5 * kRadius);
  // An unseeded reset continues the stream: another start again.
  env->reset(2);
  const TipVector seeded = as_reach(*env).tips();
  env->reset();
  EXPECT_NE(as_reach(*env).tips(), seeded);
  // The episode runs from the shifted window: the first observation shows the shifted tips.
  auto plain = ReachEnv::create_on_model(Config::parse("{}"));
  EXPECT_NE(env->reset(4), plain->reset(4));
}

// A snapshot taken mid-episode with an offset restores the window and the stream: the rest of
// the episode and the next (unseeded) start repeat bit for bit.
TEST(LearnedReach, ASnapshotWithAnInitialOffsetRepeatsTheEpisodeAndTheNextStart) {
  auto env = make(ReachEnv::kModelId, Config::parse("task: G2\ninitial_offset_mm: 25\n"));
  env->reset(9);
  for (int t = 0; t < 5; ++t) env->step(delta_on(t % 9, 0.2f));
  const Snapshot snapshot = snapshot_of(*env);
  std::vector<Observation> first;
  for (int t = 0; t < 8; ++t) first.push_back(env->step(delta_on((3 * t) % 9, -0.1f)).observation);
  first.push_back(env->reset());
  restore(*env, snapshot);
  for (int t = 0; t < 8; ++t) {
    EXPECT_EQ(env->step(delta_on((3 * t) % 9, -0.1f)).observation, first[t]) << t;
  }
  EXPECT_EQ(env->reset(), first.back());
}

TEST(LearnedReach, RefusesABadInitialOffset) {
  // A negative radius is refused by the environment, a non-finite one already by the config.
  for (const auto& [bad, why] :
       std::vector<std::pair<const char*, const char*>>{{"initial_offset_mm: -1\n", "non-negative"},
                                                        {"initial_offset_mm: .nan\n", "finite"},
                                                        {"initial_offset_mm: .inf\n", "finite"}}) {
    const std::string message =
        testing::error_message([&] { ReachEnv::create_on_model(Config::parse(bad)); });
    EXPECT_NE(message.find("initial_offset_mm"), std::string::npos) << bad << ": " << message;
    EXPECT_NE(message.find(why), std::string::npos) << bad << ": " << message;
  }
  EXPECT_THROW(ReachEnv::create_on_model(Config::parse("initial_offset_mm: far\n")), Error);
  EXPECT_THROW(ModelDynamics(std::make_shared<LinearArmModel>(), LinearArmModel::rest(), 0.0, -2.0),
               Error);
}

TEST(LearnedReach, ASnapshotRepeatsTheEpisodeBitForBit) {
  auto env = make(ReachEnv::kModelId, Config::parse("task: G2"));
  env->reset(3);
  for (int t = 0; t < 7; ++t) env->step(delta_on(t % 9, 0.2f));
  const Snapshot snapshot = snapshot_of(*env);
  std::vector<Step> first;
  for (int t = 0; t < 10; ++t) first.push_back(env->step(delta_on((2 * t) % 9, -0.1f)));
  restore(*env, snapshot);
  for (int t = 0; t < 10; ++t) {
    const Step step = env->step(delta_on((2 * t) % 9, -0.1f));
    EXPECT_EQ(step.observation, first[t].observation) << t;
    EXPECT_EQ(step.reward, first[t].reward) << t;
    EXPECT_EQ(step.terminated, first[t].terminated) << t;
  }
}

TEST(LearnedReach, SameConfigSameEpisode) {
  auto a = make(ReachEnv::kModelId), b = make(ReachEnv::kModelId);
  EXPECT_EQ(a->reset(5), b->reset(5));
  for (int t = 0; t < 30; ++t) {
    const Action action = delta_on((5 * t) % 9, (t % 3 == 0) ? -0.2f : 0.15f);
    const Step sa = a->step(action), sb = b->step(action);
    EXPECT_EQ(sa.observation, sb.observation) << t;
    EXPECT_EQ(sa.reward, sb.reward) << t;
  }
}

class LearnedReachFiles : public testing::ScratchDirectoryTest {
 protected:
  LearnedReachFiles() : ScratchDirectoryTest("learned_reach") {}
};

// A learned model opens through the installed loader and starts from the rest row of a data
// set (its first row: the arm hanging still before the signal's first command).
TEST_F(LearnedReachFiles, TheModelComesFromTheLoaderAndTheRestFromTheData) {
  PneumaticDataset data;
  data.time_s = Eigen::Vector2d(0.0, 0.1);
  data.commands_bar = PneumaticDataset::Columns::Zero(2, 9);
  data.tips_mm = PneumaticDataset::Columns::Zero(2, 9);
  data.tips_mm.row(0) << 1, 2, -200, 3, 4, -400, 5, 6, -600;
  const auto file = directory_ / "rest.csv";
  write_pneumatic_dataset(file, data);

  install_dynamics_model_loader([](const std::string& path) -> std::unique_ptr<DynamicsModel> {
    if (path != "scripted") throw Error("no model at " + path);
    return std::make_unique<LinearArmModel>(3);
  });
  auto env =
      ReachEnv::create_on_model(Config::parse("model: scripted\nrest_from: " + file.string()));
  env->reset(0);
  EXPECT_EQ(as_reach(*env).tips(), data.tips_mm.row(0).transpose());
  auto explicit_rest = ReachEnv::create_on_model(
      Config::parse("model: scripted\nrest_mm: [0, 0, -1, 0, 0, -2, 0, 0, -3]"));
  explicit_rest->reset(0);
  EXPECT_EQ(as_reach(*explicit_rest).tips()[8], -3.0);
  EXPECT_NE(testing::error_message([] {
              make(ReachEnv::kModelId, Config::parse("model: scripted"));
            }).find("rest_mm or rest_from"),
            std::string::npos);
  EXPECT_THROW(
      make(ReachEnv::kModelId, Config::parse("model: elsewhere\nrest_mm: [0,0,0,0,0,0,0,0,0]")),
      Error);
  install_dynamics_model_loader(nullptr);
  EXPECT_NE(testing::error_message([] {
              make(ReachEnv::kModelId, Config::parse("model: runs/some_model"));
            }).find("built without the dynamics layer"),
            std::string::npos);
}

TEST(LearnedReach, AModelOfAnotherShapeIsRefused) {
  class Wrong : public DynamicsModel {
   public:
    int state_dim() const override { return 9; }
    int input_dim() const override { return 6; }
    int window_length() const override { return 3; }
    double sample_period() const override { return 0.1; }
    void predict(const BatchMatrix&, BatchMatrix&) override {}
  };
  EXPECT_NE(testing::error_message([] {
              ModelDynamics(std::make_shared<Wrong>(), LinearArmModel::rest());
            }).find("9 pressures"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::envs::pneumatic
