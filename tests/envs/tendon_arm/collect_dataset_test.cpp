// The tendon arm's data protocol: the file reads back in the one data-set format, its rows keep
// the row convention (the tip of row k + 1 answers the tensions of row k), training rows come
// before test rows, and nothing is overwritten.
#include "tendril/envs/tendon_arm/collect_dataset.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/tendon_arm/robot_env.hpp"

namespace tendril::envs::tendon_arm {
namespace {

using testing::error_message;

class CollectDataset : public testing::ScratchDirectoryTest {
 protected:
  CollectDataset() : ScratchDirectoryTest("tendon_arm_collect") {}

  Config config(const std::string& extra = "") const {
    return Config::parse(
        "robot: {id: TendonArm/Robot-v0}\nduration_s: 2\ntest_duration_s: 1\n"
        "seed: 3\nsignal: {hold_s: [0.2, 0.5]}\n" +
            extra,
        "collect.yaml");
  }
};

TEST_F(CollectDataset, RowsReadBackAndReplayOnTheRobot) {
  const auto file = directory_ / "sub" / "arm.csv";
  const CollectionReport report = collect_dataset(config(), file, "test");
  EXPECT_EQ(report.train_rows, 20);
  EXPECT_EQ(report.test_rows, 10);
  const data::Table table = data::read_table(file, dataset_schema(3));
  ASSERT_EQ(table.rows(), 30);
  EXPECT_EQ(table.values, report.table.values);
  const int split = dataset_schema(3).column("split");
  for (int k = 0; k < 30; ++k) {
    EXPECT_NEAR(table.values(k, 0), 0.1 * (k < 20 ? k : k - 20), 1e-9) << "row " << k;
    EXPECT_EQ(table.values(k, split), k < 20 ? 0.0 : 1.0) << "row " << k;
  }
  // The training recording replayed on a fresh robot: each tip within the file's 1 µm rounding,
  // the tensions within [0, 6] N and redrawn at least once in 2 s of holds of at most 0.5 s.
  RobotEnv robot{ArmSpec()};
  Observation observation = robot.reset(0);
  int changes = 0;
  for (int k = 0; k < 20; ++k) {
    for (int c = 0; c < 6; ++c) {
      EXPECT_NEAR(table.values(k, 4 + c), observation[c], 1e-6) << "row " << k << " col " << c;
    }
    const Eigen::VectorXd tensions = table.values.row(k).segment(1, 3).transpose();
    EXPECT_GE(tensions.minCoeff(), 0.0);
    EXPECT_LE(tensions.maxCoeff(), 6.0);
    if (k > 0 && tensions != table.values.row(k - 1).segment(1, 3).transpose()) ++changes;
    observation = robot.step(tensions.cast<float>()).observation;
  }
  EXPECT_GE(changes, 3);
}

TEST_F(CollectDataset, NothingIsOverwrittenAndBadKeysAreNamed) {
  const auto file = directory_ / "arm.csv";
  collect_dataset(config(), file, "test");
  std::stringstream before;
  before << std::ifstream(file).rdbuf();
  EXPECT_NE(error_message([&] { collect_dataset(config(), file, "test"); }).find("exists"),
            std::string::npos);
  std::stringstream after;
  after << std::ifstream(file).rdbuf();
  EXPECT_EQ(before.str(), after.str());
  const auto other = directory_ / "other.csv";
  EXPECT_NE(error_message([&] {
              collect_dataset(Config::parse("signal: {hold_s: [2, 1]}\n", "collect.yaml"), other,
                              "test");
            }).find("collect.yaml: signal.hold_s"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              collect_dataset(Config::parse("durations: 3\n", "collect.yaml"), other, "test");
            }).find("durations"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(other));
}

}  // namespace
}  // namespace tendril::envs::tendon_arm
