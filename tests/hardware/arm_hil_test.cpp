// The pneumatic arm through its lab's two emulated devices (a 10 Hz regulator channel and a
// 100 Hz motion-capture stream, loopback UDP): with the emulator in lockstep, PneumaticArm/
// Robot-v0 over the bridge equals the twin version bit for bit (the pressures and marker
// positions travel as the doubles they are), down to a whole GPRCA trial; the bridge's faults
// are answered as the limb's are.
#include <gtest/gtest.h>

#include <cmath>

#include "tendril/adapt/gprca_trials.hpp"
#include "tendril/adapt/task_reaching_robot.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/envs/pneumatic/bridge_robot_env.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"
#include "tendril/envs/pneumatic/robot_env.hpp"
#include "tendril/hardware/arm_emulator.hpp"
#include "tendril/hardware/udp_transport.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::hardware {
namespace {

// A free loopback UDP port for the motion capture to stream to.
int free_port() {
  UdpTransport probe("127.0.0.1", 0, "", 0);
  return probe.local_port();
}

struct Lab {
  explicit Lab(const Config& robot_params, double host_wait_s = 30.0) {
    mocap_port = free_port();
    ArmEmulatorSettings settings;
    settings.spec = envs::pneumatic::arm_spec_from(robot_params);
    settings.mocap_port = mocap_port;
    settings.host_wait_s = host_wait_s;
    emulator = std::make_unique<ArmEmulator>(settings);
    emulator->start();
  }
  // `backend: bridge, bridge: {...}` as a flow mapping's entries.
  std::string bridge_entries(const std::string& extra = "") const {
    return "backend: bridge, bridge: {udp_port: " + std::to_string(emulator->command_port()) +
           ", mocap_port: " + std::to_string(mocap_port) + extra + "}";
  }
  std::string bridge_yaml(const std::string& extra = "") const {
    return "{" + bridge_entries(extra) + "}";
  }
  int mocap_port = 0;
  std::unique_ptr<ArmEmulator> emulator;
};

Action pressures(int step) {
  Action action(9);
  for (int k = 0; k < 9; ++k) {
    action[k] = static_cast<float>(0.75 + 0.7 * std::sin(0.15 * step + 0.8 * k));
  }
  return action;
}

TEST(ArmHil, ATrialThroughTheLabsDevicesEqualsTheTwins) {
  const Config twin_params = Config::parse("observe_pressures: true");
  auto twin = envs::pneumatic::RobotEnv::create(twin_params);
  Lab lab(twin_params);
  auto bridged = envs::pneumatic::RobotEnv::create(
      Config::parse("{observe_pressures: true, " + lab.bridge_entries() + "}"));
  ASSERT_EQ(bridged->observation_space().size(), twin->observation_space().size());
  EXPECT_EQ(bridged->action_space().high(), twin->action_space().high());
  EXPECT_EQ(bridged->reset(4), twin->reset(4));
  for (int t = 0; t < envs::pneumatic::RobotEnv::kTrialSteps; ++t) {
    const Step a = twin->step(pressures(t));
    const Step b = bridged->step(pressures(t));
    ASSERT_EQ(b.observation, a.observation) << t;
    for (const auto& [key, value] : a.info.entries()) {
      ASSERT_EQ(*b.info.get(key), value) << key << " at " << t;
    }
    EXPECT_GT(*b.info.get("latency_s"), 0.0);
  }
  // And a second trial without a seed: the twin's streams continue on both.
  EXPECT_EQ(bridged->reset(), twin->reset());
  EXPECT_EQ(bridged->step(pressures(3)).observation, twin->step(pressures(3)).observation);
  EXPECT_EQ(lab.emulator->samples(), 10);
}

// A fixed small push on every chamber: enough to move the arm through a GPRCA trial.
class SteadyPolicy final : public rl::Policy {
 public:
  SteadyPolicy(Space observation, Space action) : rl::Policy(observation, action) {}
  std::string kind() const override { return "scripted"; }

 protected:
  void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations, bool, Rng&,
                   Eigen::MatrixXf& actions) const override {
    actions = Eigen::MatrixXf::Constant(action_space().size(), observations.cols(), 0.05f);
  }
  void write(ArchiveWriter&) const override {}
};

TEST(ArmHil, AGprcaTrialOnTheEmulatedLabEqualsTheTwins) {
  const std::string task = "observe_command: true\n";
  auto twin_robot = std::make_unique<adapt::TaskReachingRobot>(
      envs::pneumatic::ReachEnv::create_on_robot(Config::parse(task)));
  Lab lab(Config::parse("{}"));
  auto bridge_robot =
      std::make_unique<adapt::TaskReachingRobot>(envs::pneumatic::ReachEnv::create_on_robot(
          Config::parse(task + "robot: " + lab.bridge_yaml())));
  const SteadyPolicy policy(twin_robot->env().observation_space(),
                            twin_robot->env().action_space());
  adapt::GprcaTrialsOptions options;
  options.max_trials = 1;
  options.steps_per_trial = 40;
  options.search_between_trials = false;
  adapt::TaskHistoryModel twin_model(
      envs::pneumatic::ReachEnv::create_on_model(Config::parse("{}")));
  adapt::TaskHistoryModel bridge_model(
      envs::pneumatic::ReachEnv::create_on_model(Config::parse("{}")));
  const adapt::AdaptationResult expected = run_gprca(*twin_robot, twin_model, policy, options, 2);
  const adapt::AdaptationResult got = run_gprca(*bridge_robot, bridge_model, policy, options, 2);
  ASSERT_EQ(got.steps.size(), expected.steps.size());
  ASSERT_GT(got.steps.size(), 10u);
  for (size_t i = 0; i < got.steps.size(); ++i) {
    ASSERT_EQ(got.steps[i].state, expected.steps[i].state) << i;
    ASSERT_EQ(got.steps[i].command, expected.steps[i].command) << i;
    ASSERT_EQ(got.steps[i].reference, expected.steps[i].reference) << i;
  }
  EXPECT_EQ(got.trials[0].final_goal_distance, expected.trials[0].final_goal_distance);
}

TEST(ArmHil, LostCaptureFramesAndAFrozenOrSilentCaptureAreAnswered) {
  Lab lab(Config::parse("{}"), /*host_wait_s=*/0.05);
  auto env = envs::pneumatic::RobotEnv::create(
      Config::parse(lab.bridge_yaml(", frozen_frames: 30, frame_timeout_s: 0.3")));
  auto& bridge = dynamic_cast<envs::pneumatic::BridgeRobotEnv&>(*env).bridge();
  env->reset(1);
  env->step(pressures(0));
  lab.emulator->freeze_capture(true);
  EXPECT_THROW(
      {
        for (int t = 0; t < 5; ++t) env->step(pressures(t));
      },
      Error);
  EXPECT_EQ(bridge.log().count("frozen_sensor"), 1);
  EXPECT_EQ(bridge.log().count("safe_command"), 1);
  lab.emulator->freeze_capture(false);
  env->reset(1);
  env->step(pressures(0));
  lab.emulator->silence_capture(true);
  EXPECT_THROW(env->step(pressures(1)), Error);
  EXPECT_EQ(bridge.log().count("stale_sensor"), 1);
  lab.emulator->silence_capture(false);
  // Above the ceiling: clamped, logged, and the regulators never see more than 1.5 bar.
  env->reset(1);
  Action high = Action::Constant(9, 1.5f);
  env->step(high);
  EXPECT_EQ(bridge.log().count("clamp"), 0);
  bridge.command(physics::pneumatic::ChamberVector::Constant(2.0));
  EXPECT_EQ(bridge.log().count("clamp"), 1);
}

TEST(RobotBackends, AnUnknownBackendOrAMissingLinkIsAnErrorNamingTheKey) {
  for (const char* yaml : {"{backend: hardware}", "{backend: bridge, bridge: {}}"}) {
    try {
      envs::pneumatic::RobotEnv::create(Config::parse(yaml));
      FAIL() << yaml;
    } catch (const Error& error) {
      const std::string text = error.what();
      EXPECT_TRUE(text.find("backend") != std::string::npos ||
                  text.find("udp_port") != std::string::npos)
          << text;
    }
  }
}

}  // namespace
}  // namespace tendril::hardware
