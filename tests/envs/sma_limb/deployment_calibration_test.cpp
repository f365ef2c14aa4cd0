// Which calibration a controller made in a learned model of the limb is deployed with.
#include "tendril/envs/sma_limb/deployment_calibration.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/envs/sma_limb/limb_calibration.hpp"

namespace tendril::envs::sma_limb {
namespace {

using tendril::testing::error_message;

class DeploymentCalibration : public tendril::testing::ScratchDirectoryTest {
 protected:
  DeploymentCalibration() : ScratchDirectoryTest("deployment_calibration") {}

  void write(const std::filesystem::path& file, const std::string& text) const {
    std::ofstream(file, std::ios::binary) << text;
  }

  // A calibration of the stiff limb with its true offsets; `upper` changes its table.
  std::string calibration(const std::string& name, int upper = 36) const {
    LimbCalibration c = LimbCalibration::nominal("stiff");
    c.zero_offset_deg = Eigen::Vector2d(-9.99, -11.99);
    c.upper_pwm.fill(upper);
    const std::filesystem::path file = directory_ / name;
    c.save(file);
    return file.string();
  }

  // A model's run directory whose data set's header names `used` (none: no such line).
  std::filesystem::path model(const std::string& used) const {
    const std::filesystem::path data = directory_ / "prepared.csv";
    write(data, "# format: tendril.sma_limb.prepared v1\n# limb: stiff\n" +
                    (used.empty() ? std::string() : "# calibration: " + used + "\n") +
                    "# seed: 1\ntime_s,theta_x\n0,0\n");
    const std::filesystem::path run = directory_ / "model";
    std::filesystem::create_directories(run);
    write(run / "config.yaml", "data:\n  file: " + data.string() + "\nseed: 1\n");
    return run;
  }
};

TEST_F(DeploymentCalibration, IsReadFromTheModelsDataSet) {
  const std::string file = calibration("calibration_stiff.yaml");
  EXPECT_EQ(model_calibration(model(file)), file);
  EXPECT_EQ(model_calibration(model("none")), "none");
  EXPECT_EQ(model_calibration(model("")), std::nullopt);              // no header line
  EXPECT_EQ(model_calibration(directory_ / "absent"), std::nullopt);  // no run
  write(directory_ / "model" / "config.yaml",
        "data:\n  file: " + (directory_ / "moved.csv").string() + "\n");
  EXPECT_EQ(model_calibration(directory_ / "model"), std::nullopt);  // data set moved
}

TEST_F(DeploymentCalibration, DefaultsToTheModelsAndRefusesAnother) {
  const std::string trained = calibration("calibration_stiff.yaml");
  const std::string copy = calibration("copy.yaml");        // the same table and offsets
  const std::string other = calibration("other.yaml", 38);  // another table
  EXPECT_EQ(deployment_calibration("", trained, "stiff", "track"), trained);
  EXPECT_EQ(deployment_calibration(trained, trained, "stiff", "track"), trained);
  EXPECT_EQ(deployment_calibration(copy, trained, "stiff", "track"), copy);
  const std::string table =
      error_message([&] { deployment_calibration(other, trained, "stiff", "track"); });
  EXPECT_NE(table.find("track"), std::string::npos) << table;
  EXPECT_NE(table.find(trained), std::string::npos) << table;
  EXPECT_NE(table.find(other), std::string::npos) << table;
  // The accident this guards against: a policy of the calibrated limb on raw readings.
  const std::string raw =
      error_message([&] { deployment_calibration("none", trained, "stiff", "track"); });
  EXPECT_NE(raw.find("'none'"), std::string::npos) << raw;
  // A model of uncalibrated data deploys uncalibrated, and only so.
  EXPECT_EQ(deployment_calibration("", std::string("none"), "stiff", "track"), "none");
  EXPECT_NE(error_message(
                [&] { deployment_calibration(trained, std::string("none"), "stiff", "track"); }),
            "no error");
}

// The robustness test of seed 001 §5.2.2: the stiff limb's policy on the soft limb, which runs on
// its own calibration — named, never assumed, never `none`.
TEST_F(DeploymentCalibration, AnotherLimbNeedsItsOwnCalibration) {
  const std::string trained = calibration("calibration_stiff.yaml");
  LimbCalibration soft = LimbCalibration::nominal("soft");
  soft.save(directory_ / "calibration_soft.yaml");
  const std::string own = (directory_ / "calibration_soft.yaml").string();
  EXPECT_EQ(deployment_calibration(own, trained, "soft", "track"), own);
  const std::string missing =
      error_message([&] { deployment_calibration("", trained, "soft", "track"); });
  EXPECT_NE(missing.find("soft limb"), std::string::npos) << missing;
  EXPECT_NE(error_message([&] { deployment_calibration("none", trained, "soft", "track"); }),
            "no error");
}

TEST_F(DeploymentCalibration, MustBeNamedWhenTheModelDoesNotSay) {
  const std::string file = calibration("calibration_stiff.yaml");
  EXPECT_EQ(deployment_calibration(file, std::nullopt, "stiff", "track"), file);
  EXPECT_EQ(deployment_calibration("none", std::nullopt, "stiff", "track"), "none");
  const std::string message =
      error_message([] { deployment_calibration("", std::nullopt, "stiff", "tendril track"); });
  EXPECT_NE(message.find("tendril track"), std::string::npos) << message;
  EXPECT_NE(message.find("--calibration"), std::string::npos) << message;
}

}  // namespace
}  // namespace tendril::envs::sma_limb
