// The SMA limb's whole pipeline through its real firmware: the ELF that would be flashed onto
// the Arduino runs in simavr, wired to the twin; the host reaches it over a pseudo-terminal
// through the bridge. With the emulator in lockstep (no added latency, the host's computing
// costing no robot time) every number must equal the direct twin path's, bit for bit: the
// firmware passes PWM through unchanged, the sensor's 0.1° counts travel as integers and are
// scaled back exactly, and the twin integrates each sensor interval with the command that
// followed its reading (docs/hardware.md).
#include <gtest/gtest.h>

#include "limb_hil_support.hpp"
#include "tendril/control/reference_patterns.hpp"
#include "tendril/control/tracking_policy.hpp"
#include "tendril/control/waypoint_follower.hpp"
#include "tendril/envs/runner/tracking_record.hpp"
#include "tendril/envs/sma_limb/bridge_limb_robot.hpp"
#include "tendril/envs/sma_limb/calibrate.hpp"
#include "tendril/envs/sma_limb/collect.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#include "tendril/envs/sma_limb/throttle_sources.hpp"
#include "tendril/envs/sma_limb/twin_limb_robot.hpp"

namespace tendril::hardware {
namespace {

using envs::sma_limb::SmaLimbEnv;
using testing::bridge_env_params;
using testing::bridge_to;
using testing::emulator_settings;

void expect_same_log(const envs::sma_limb::LimbLog& twin, const envs::sma_limb::LimbLog& bridge) {
  ASSERT_EQ(twin.size(), bridge.size());
  for (size_t i = 0; i < twin.size(); ++i) {
    ASSERT_EQ(twin.time_s[i], bridge.time_s[i]) << "row " << i;
    ASSERT_EQ(twin.angles_deg[i], bridge.angles_deg[i]) << "row " << i;
    ASSERT_EQ(twin.throttles[i], bridge.throttles[i]) << "row " << i;
    ASSERT_EQ(twin.pwm[i], bridge.pwm[i]) << "row " << i;
  }
  EXPECT_EQ(twin.cutoffs, bridge.cutoffs);
}

// The twin with the firmware's cut-off (docs/protocol.md): while the newest reading is at or
// beyond 100° on either axis the coils stay off. Calibration drives the twin directly, below
// SmaLimbEnv, which otherwise applies the cut-off on the host.
class CutoffTwin final : public envs::sma_limb::LimbRobot {
 public:
  envs::sma_limb::LimbSample reset(uint64_t seed) override { return last_ = twin_.reset(seed); }
  envs::sma_limb::LimbSample command(const std::array<int, 4>& pwm) override {
    const bool cutoff = last_.angles_deg.cwiseAbs().maxCoeff() >= 100.0;
    return last_ = twin_.command(cutoff ? std::array<int, 4>{} : pwm);
  }
  std::string description() const override { return twin_.description(); }

 private:
  envs::sma_limb::TwinLimbRobot twin_{physics::SmaLimbSpec::stiff()};
  envs::sma_limb::LimbSample last_;
};

TEST(LimbHil, CalibrationSweepsThroughTheFirmwareEqualTheTwins) {
  // Shortened sweeps (the thesis' holds are 2.5 s, its cool-downs 2 min): 19 holds, 25 s of
  // robot time.
  envs::sma_limb::CalibrationSettings settings;
  settings.rest_s = 0.6;
  settings.hold_s = 0.8;
  settings.cooldown_s = 0.5;
  settings.start_pwm = 30;
  CutoffTwin twin;
  const auto expected = envs::sma_limb::calibrate(twin, settings, "stiff", 5);

  LimbEmulator emulator(emulator_settings());
  emulator.start();
  envs::sma_limb::BridgeLimbRobot robot(bridge_to(emulator));
  const auto got = envs::sma_limb::calibrate(robot, settings, "stiff", 5);
  emulator.stop();

  EXPECT_EQ(got.calibration.lower_pwm, expected.calibration.lower_pwm);
  EXPECT_EQ(got.calibration.upper_pwm, expected.calibration.upper_pwm);
  EXPECT_EQ(got.calibration.zero_offset_deg, expected.calibration.zero_offset_deg);
  EXPECT_EQ(got.robot_time_s, expected.robot_time_s);
  ASSERT_EQ(got.holds.size(), expected.holds.size());
  ASSERT_GE(got.holds.size(), 10u);
  for (size_t h = 0; h < got.holds.size(); ++h) {
    EXPECT_EQ(got.holds[h].pwm, expected.holds[h].pwm);
    EXPECT_EQ(got.holds[h].angle_deg, expected.holds[h].angle_deg) << "hold " << h;
    EXPECT_EQ(got.holds[h].time_s, expected.holds[h].time_s) << "hold " << h;
  }
  // The bridge saw no fault on the way.
  EXPECT_EQ(robot.bridge().log().events().size(), 0u);
  EXPECT_EQ(robot.bridge().link().parser().errors(), 0u);
}

TEST(LimbHil, AMinuteOfExplorationDataThroughTheFirmwareEqualsTheTwins) {
  envs::sma_limb::CollectSettings settings;
  settings.duration_s = 60.0;
  settings.cutoff_cooldown_s = 5.0;
  auto twin = SmaLimbEnv::create(Config::parse("limb: stiff\ncalibration: none"));
  envs::sma_limb::CountBasedExploration twin_source;
  const auto expected = envs::sma_limb::collect(*twin, twin_source, settings, 21);

  LimbEmulator emulator(emulator_settings());
  emulator.start();
  auto bridged = SmaLimbEnv::create(bridge_env_params(emulator.port()));
  envs::sma_limb::CountBasedExploration bridge_source;
  const auto got = envs::sma_limb::collect(*bridged, bridge_source, settings, 21);
  emulator.stop();

  ASSERT_GT(expected.size(), 700u);  // 60 s at 55–75 ms a reading
  expect_same_log(expected, got);
  // Every reading crossed the wire: the firmware served one per row (plus the rest between).
  EXPECT_GE(emulator.readings(), static_cast<int>(got.size()));
}

// The thesis' tracking loop (PID baseline along the circle) closed through the firmware.
TEST(LimbHil, AClosedLoopControllerThroughTheFirmwareTracksAsOnTheTwin) {
  const Eigen::Matrix2Xd path = control::reference_pattern("circle");
  auto run_on = [&](Env& env, Info* info) {
    const control::TrackingPolicy pid =
        testing::raw_reading_tracking(env, std::make_shared<control::PidController>(), path);
    testing::LastInfo last;
    envs::TrackingRun run = envs::track_path(pid, env, 200, 3, {&last});
    if (info != nullptr) *info = last.info;
    return run;
  };
  auto twin = SmaLimbEnv::create(Config::parse("limb: stiff\ncalibration: none"));
  Info twin_info;
  const envs::TrackingRun expected = run_on(*twin, &twin_info);

  LimbEmulator emulator(emulator_settings());
  emulator.start();
  auto bridged = SmaLimbEnv::create(bridge_env_params(emulator.port()));
  Info bridge_info;
  const envs::TrackingRun got = run_on(*bridged, &bridge_info);
  emulator.stop();

  EXPECT_EQ(got.times, expected.times);
  EXPECT_EQ(got.angles, expected.angles);
  EXPECT_EQ(got.throttles, expected.throttles);
  EXPECT_EQ(got.finished, expected.finished);
  EXPECT_EQ(got.rmse_deg, expected.rmse_deg);
  // The same info keys and values, plus the bridge's two.
  for (const auto& [key, value] : twin_info.entries()) {
    ASSERT_TRUE(bridge_info.has(key)) << key;
    EXPECT_EQ(*bridge_info.get(key), value) << key;
  }
  EXPECT_EQ(bridge_info.entries().size(), twin_info.entries().size() + 2);
  EXPECT_GT(*bridge_info.get("elapsed_s"), 0.0);
  EXPECT_GT(*bridge_info.get("latency_s"), 0.0);
  EXPECT_EQ(bridged->observation_space().size(), twin->observation_space().size());
  EXPECT_EQ(bridged->action_space().size(), twin->action_space().size());
}

}  // namespace
}  // namespace tendril::hardware
