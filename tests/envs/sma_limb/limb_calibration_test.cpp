// The throttle table of the thesis (§4.1.2, §4.2.1) and the calibration file.
#include "tendril/envs/sma_limb/limb_calibration.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

namespace tendril::envs::sma_limb {
namespace {

using tendril::testing::error_message;

// The worked example of §4.2.1: +x bounds 35 (upper) / 20 (lower), −x 36 / 19.
LimbCalibration thesis_example() {
  LimbCalibration calibration = LimbCalibration::nominal("stiff");
  calibration.lower_pwm = {20, 19, 20, 19};
  calibration.upper_pwm = {35, 36, 35, 36};
  return calibration;
}

TEST(LimbCalibration, TheThrottleTableMatchesTheThesisExample) {
  const LimbCalibration calibration = thesis_example();
  EXPECT_EQ(calibration.pwm_for(-10, 0), (std::array<int, 4>{0, 36, 0, 0}));
  EXPECT_EQ(calibration.pwm_for(-1, 0), (std::array<int, 4>{0, 19, 0, 0}));
  EXPECT_EQ(calibration.pwm_for(10, 0), (std::array<int, 4>{35, 0, 0, 0}));
  EXPECT_EQ(calibration.pwm_for(1, 0), (std::array<int, 4>{20, 0, 0, 0}));
  EXPECT_EQ(calibration.pwm_for(0, 0), (std::array<int, 4>{0, 0, 0, 0}));
  // Linear in between: 20 + (j − 1) · 15 / 9 rounded; j = 4 → 25, j = 7 → 30.
  EXPECT_EQ(calibration.pwm_for(4, 7), (std::array<int, 4>{25, 0, 30, 0}));
  // −y: 19 + (j − 1) · 17 / 9; j = 5 → 26.56 → 27.
  EXPECT_EQ(calibration.pwm_for(0, -5), (std::array<int, 4>{0, 0, 0, 27}));
}

TEST(LimbCalibration, ThrottlesAreRoundedAndSaturatedAtTheTablesEnds) {
  const LimbCalibration calibration = thesis_example();
  EXPECT_EQ(calibration.pwm_for(0.4, -0.6), (std::array<int, 4>{0, 0, 0, 19}));
  EXPECT_EQ(calibration.pwm_for(9.6, 0), calibration.pwm_for(10, 0));
  EXPECT_EQ(calibration.pwm_for(14, -30), (std::array<int, 4>{35, 0, 0, 36}));
}

TEST(LimbCalibration, NominalBoundsAreTheThesisPercentages) {
  const LimbCalibration stiff = LimbCalibration::nominal("stiff");
  const LimbCalibration soft = LimbCalibration::nominal("soft");
  EXPECT_NEAR(stiff.lower_pwm[0] / 255.0, 0.07, 0.002);
  EXPECT_NEAR(stiff.upper_pwm[2] / 255.0, 0.15, 0.002);
  EXPECT_NEAR(soft.upper_pwm[3] / 255.0, 0.11, 0.002);
  EXPECT_NE(error_message([] { LimbCalibration::nominal("medium"); }), "no error");
}

class CalibrationFile : public tendril::testing::ScratchDirectoryTest {
 protected:
  CalibrationFile() : ScratchDirectoryTest("limb_calibration") {}
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto file = directory_ / name;
    std::ofstream(file) << text;
    return file;
  }
};

TEST_F(CalibrationFile, RoundTripsExactlyAndNeverOverwrites) {
  LimbCalibration calibration = thesis_example();
  calibration.zero_offset_deg = Eigen::Vector2d(-10.04, -11.96);
  calibration.noise_floor_deg_s = 6.15;
  const auto file = directory_ / "calibration.yaml";
  calibration.save(file);
  const LimbCalibration loaded = LimbCalibration::load(file);
  EXPECT_EQ(loaded.limb, "stiff");
  EXPECT_EQ(loaded.lower_pwm, calibration.lower_pwm);
  EXPECT_EQ(loaded.upper_pwm, calibration.upper_pwm);
  EXPECT_EQ(loaded.zero_offset_deg, calibration.zero_offset_deg);
  EXPECT_EQ(loaded.noise_floor_deg_s, calibration.noise_floor_deg_s);
  EXPECT_NE(error_message([&] { calibration.save(file); }).find("already exists"),
            std::string::npos);
}

TEST_F(CalibrationFile, MalformedFilesAreRejectedNamingFileAndKey) {
  const std::string good =
      "limb: soft\nzero_offset_deg: [1.0, 2.0]\nnoise_floor_deg_per_s: 5.0\ncoils:\n"
      "  pos_x: {lower_pwm: 18, upper_pwm: 28}\n  neg_x: {lower_pwm: 18, upper_pwm: 28}\n"
      "  pos_y: {lower_pwm: 18, upper_pwm: 28}\n  neg_y: {lower_pwm: 18, upper_pwm: 28}\n";
  EXPECT_EQ(error_message([&] { LimbCalibration::load(write("good.yaml", good)); }), "no error");

  std::string missing = good;
  missing.replace(missing.find("  neg_y"), std::string::npos, "");
  const std::string message =
      error_message([&] { LimbCalibration::load(write("missing.yaml", missing)); });
  EXPECT_NE(message.find("missing.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("coils.neg_y.lower_pwm"), std::string::npos) << message;

  const std::string unknown = good + "gain: 2\n";
  EXPECT_NE(
      error_message([&] { LimbCalibration::load(write("unknown.yaml", unknown)); }).find("gain"),
      std::string::npos);

  std::string inverted = good;
  inverted.replace(inverted.find("pos_y: {lower_pwm: 18, upper_pwm: 28}"), 37,
                   "pos_y: {lower_pwm: 30, upper_pwm: 28}");
  const std::string bounds =
      error_message([&] { LimbCalibration::load(write("inverted.yaml", inverted)); });
  EXPECT_NE(bounds.find("inverted.yaml"), std::string::npos) << bounds;
  EXPECT_NE(bounds.find("pos_y"), std::string::npos) << bounds;

  std::string three = good;
  three.replace(three.find("[1.0, 2.0]"), 10, "[1, 2, 3]");
  EXPECT_NE(error_message([&] {
              LimbCalibration::load(write("three.yaml", three));
            }).find("zero_offset_deg"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::envs::sma_limb
