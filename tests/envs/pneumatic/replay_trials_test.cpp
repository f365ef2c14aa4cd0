#include "tendril/envs/pneumatic/replay_trials.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/learned/model_loader.hpp"
#include "tendril/envs/pneumatic/open_loop_reach.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"

namespace tendril::envs::pneumatic {
namespace {

using testing::error_message;

class ReplayTrials : public testing::ScratchDirectoryTest {
 protected:
  ReplayTrials() : ScratchDirectoryTest("replay_trials") {}
};

const char* kDeterministic =
    "robot:\n  params: {stochastic: false}\nscenarios: [S0, S3]\ntrials: 3\nduration_s: 3\n"
    "seed: 4\n";

// With every stochastic effect off the trials of one scenario repeat exactly: S0's distances
// from its base trial, the reference, are 0; disabling a chamber of module 3 (S3) moves module
// 3's tip by millimetres under the same trajectory.
TEST_F(ReplayTrials, TheDeterministicTwinRepeatsAndDamageShowsAsAGap) {
  const ReplayReport report = replay_trials(Config::parse(kDeterministic, "replay.yaml"));
  ASSERT_EQ(report.rows.size(), 2u * 3u * 3u);
  for (const ReplayReport::Row& row : report.rows) {
    EXPECT_EQ(row.mad_from_own_base_mm, 0.0) << row.scenario << " " << row.trial;
    if (row.scenario == "S0") {
      EXPECT_EQ(row.mad_from_reference_mm, 0.0);
    }
    if (row.scenario == "S3" && row.module == 3) {
      EXPECT_GT(row.mad_from_reference_mm, 1.0);
    }
  }
  EXPECT_EQ(report.module_3_gap_mm.rows(), 30);
  EXPECT_EQ(report.module_3_gap_mm.col(0).maxCoeff(), 0.0);
  EXPECT_GT(report.module_3_gap_mm.col(1).maxCoeff(), 1.0);

  write_replay_report(report, directory_, "tendril data replay r.yaml");
  std::ifstream summary(directory_ / "replay_gap.csv");
  std::string first, header;
  std::getline(summary, first);
  std::getline(summary, header);
  EXPECT_EQ(first, "# tendril data replay r.yaml");
  EXPECT_EQ(header, "scenario,trial,module,mad_from_reference_mm,mad_from_own_base_mm");
  EXPECT_NE(error_message([&] { write_replay_report(report, directory_, "again"); }).find("exists"),
            std::string::npos);
}

// A model that stays at the rest it starts from, whatever the pressures.
class StillModel : public DynamicsModel {
 public:
  int state_dim() const override { return 9; }
  int input_dim() const override { return 9; }
  int window_length() const override { return 3; }
  double sample_period() const override { return 0.1; }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override {
    next_states = windows.rightCols(18).leftCols(9);  // the newest row's tips
  }
};

// Fig. 6 proper: the learned model run open loop is the reference. A model that never moves
// from the rest makes every trial's MAD the arm's mean excursion from the rest: the same for
// every trial of the deterministic twin, and positive for S0 too.
TEST_F(ReplayTrials, ALearnedModelCanBeTheReference) {
  install_dynamics_model_loader([](const std::string& path) -> std::unique_ptr<DynamicsModel> {
    if (path != "still") throw Error("no model at " + path);
    return std::make_unique<StillModel>();
  });
  PneumaticDataset data;
  data.time_s = Eigen::Vector2d(0.0, 0.1);
  data.commands_bar = PneumaticDataset::Columns::Zero(2, 9);
  data.tips_mm = PneumaticDataset::Columns::Zero(2, 9);
  data.tips_mm.row(0) << 0, 0, -199.3, 0, 0, -398.6, 0, 0, -597.9;
  const auto rest = directory_ / "rest.csv";
  write_pneumatic_dataset(rest, data);
  const std::string model = "reference_model: {model: still, rest_from: " + rest.string() + "}\n";
  const ReplayReport report = replay_trials(Config::parse(kDeterministic + model, "replay.yaml"));
  ASSERT_EQ(report.rows.size(), 18u);
  for (const ReplayReport::Row& row : report.rows) {
    EXPECT_GT(row.mad_from_reference_mm, 0.5) << row.scenario << " " << row.module;
    EXPECT_EQ(row.mad_from_reference_mm,
              report.rows[row.module - 1 + (row.scenario == "S3" ? 9 : 0)].mad_from_reference_mm);
  }
  EXPECT_NE(
      error_message([&] {
        replay_trials(Config::parse(
            std::string(kDeterministic) + "reference_model: {model: still}\n", "replay.yaml"));
      }).find("rest_from"),
      std::string::npos);
  install_dynamics_model_loader(nullptr);
}

TEST_F(ReplayTrials, WithEffectsOnTrialsDifferAndBadKeysAreNamed) {
  const ReplayReport report = replay_trials(Config::parse(
      "robot:\n  params: {stochastic: true}\nscenarios: [S0]\ntrials: 3\nduration_s: 2\n",
      "replay.yaml"));
  EXPECT_EQ(report.rows[0].mad_from_reference_mm, 0.0);     // trial 1 is the reference
  EXPECT_GT(report.rows.back().mad_from_own_base_mm, 0.0);  // trial 3, module 3
  EXPECT_NE(
      error_message([] {
        replay_trials(Config::parse("scenarios: [S0, S9]\ntrials: 1\nduration_s: 0.5\n", "r.yaml"));
      }).find("S9"),
      std::string::npos);
  EXPECT_NE(error_message([] {
              replay_trials(Config::parse("trial: 3\nduration_s: 0.5\n", "r.yaml"));
            }).find("trial"),
            std::string::npos);
}

// With every effect off the twin is its own perfect model: the open-loop plan ends exactly where
// the model put it in every trial; a damaged chamber makes it miss.
TEST_F(ReplayTrials, OpenLoopPlansReplayExactlyOnTheDeterministicTwin) {
  OpenLoopOptions options = open_loop_options(
      Config::parse("goals: [main]\ntrials: 2\nsearch_evaluations: 25\n", "o.yaml"));
  const Config params = Config::parse("stochastic: false\n", "p.yaml");
  const OpenLoopReport report = open_loop_reach(params, {"S0", "S1"}, options);
  ASSERT_EQ(report.goals.size(), 1u);
  ASSERT_EQ(report.rows.size(), 4u);
  EXPECT_LT(report.goals[0].model_distance, 60.0);  // 25 evaluations get it on its way
  for (const OpenLoopReport::Row& row : report.rows) {
    if (row.scenario == "S0") {
      EXPECT_EQ(row.final_distance_mm, report.goals[0].model_distance);
    } else {
      EXPECT_GT(std::abs(row.final_distance_mm - report.goals[0].model_distance), 1.0);
    }
  }
  write_open_loop_report(report, directory_, "cmd");
  EXPECT_TRUE(std::filesystem::exists(directory_ / "open_loop_reach.csv"));
  EXPECT_THROW(open_loop_options(Config::parse("goals: [G7]\n", "o.yaml")), Error);
}

}  // namespace
}  // namespace tendril::envs::pneumatic
