// `tendril robot`: the link to a real robot — run an emulator of one (the SMA limb's firmware
// in simavr on a pseudo-terminal, the pneumatic arm's lab on UDP), check a connection
// (handshake, round trips, sensor and control rates, limits), and deploy a trained policy on
// the robot through the bridge, optionally through its safety filter (docs/hardware.md).
#include <atomic>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>

#include "command_line.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/arm_params.hpp"
#include "tendril/hardware/arm_bridge.hpp"
#include "tendril/hardware/arm_emulator.hpp"
#include "tendril/hardware/deploy.hpp"
#include "tendril/hardware/limb_bridge.hpp"
#include "tendril/hardware/link_check.hpp"
#include "tendril/hardware/serial_transport.hpp"
#include "tendril/hardware/transport_config.hpp"
#include "tendril/hardware/udp_transport.hpp"
#ifdef TENDRIL_WITH_SIMAVR
#include "tendril/hardware/simavr/limb_emulator.hpp"
#endif
#ifdef TENDRIL_WITH_RL
#include "run_policy.hpp"
#endif
#ifdef TENDRIL_WITH_SAFETY
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_filter.hpp"
#endif

namespace tendril::apps {

namespace {

constexpr const char* kUsage =
    "usage: tendril robot emulate limb [--link PATH] [--limb stiff|soft] [--pace "
    "realtime|lockstep]\n"
    "                                  [--firmware ELF] [--seed S]\n"
    "       tendril robot emulate arm [--command-port P] [--mocap-port P] [--pace ...]\n"
    "                                 [--set <PneumaticArm/Robot-v0 param>=V ...]\n"
    "       tendril robot check limb --port DEVICE [--baud B] [--pings N] [--steps N]\n"
    "       tendril robot check arm --udp-port P --mocap-port P [--pings N] [--steps N]\n"
    "       tendril robot deploy <run-dir> [--set env.params.backend=bridge ...] [--best]\n"
    "                            [--filter [--epsilon E]] [--episodes N] [--steps N] [--seed S]\n"
    "                            [--csv FILE]\n";

std::atomic<bool> interrupted{false};

void on_signal(int) { interrupted = true; }

void catch_signals() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

int emulate(const std::vector<std::string>& args) {
  const CommandLine line = CommandLine::parse(
      args, {"link", "limb", "pace", "firmware", "seed", "command-port", "mocap-port"}, {});
  require(line.positional.size() == 1, "expected `limb` or `arm`", "tendril robot emulate");
  const std::string robot = line.positional.front();
  const hardware::EmulatorPace pace = hardware::pace_from(line.value("pace", "realtime"), "--pace");
  catch_signals();
  if (robot == "limb") {
#ifdef TENDRIL_WITH_SIMAVR
    hardware::LimbEmulatorSettings settings;
    settings.firmware = line.value("firmware", TENDRIL_FIRMWARE_ELF);
    settings.link = line.value("link", "/tmp/tendril-limb");
    settings.spec = physics::SmaLimbSpec::variant(line.value("limb", "stiff"));
    settings.seed = line.unsigned_integer("seed", 0);
    settings.pace = pace;
    hardware::LimbEmulator emulator(settings);
    std::printf("SMA limb firmware %s in simavr; its serial port: %s (%s)\nCtrl-C stops it.\n",
                settings.firmware.c_str(), settings.link.c_str(), emulator.port().c_str());
    std::fflush(stdout);
    emulator.run_until([] { return interrupted.load(); }, 1e9);
    std::printf("stopped after %.3f s of robot time, %d readings, %d host frames\n",
                emulator.time_s(), emulator.readings(), emulator.host_frames());
    return 0;
#else
    throw Error("this build has no simavr (libsimavr-dev) or no avr-gcc", "tendril robot emulate");
#endif
  }
  require(robot == "arm", "expected `limb` or `arm`, got '" + robot + "'", "tendril robot emulate");
  hardware::ArmEmulatorSettings settings;
  // The twin's parameters as PneumaticArm/Robot-v0 takes them, from --set key=value.
  Config params = Config::parse("{}");
  for (const auto& [key, value] : line.overrides) params.set(key, value);
  settings.spec = envs::pneumatic::arm_spec_from(params);
  settings.command_port = static_cast<int>(line.integer("command-port", 51000, 1, 65535));
  settings.mocap_port = static_cast<int>(line.integer("mocap-port", 51001, 1, 65535));
  settings.pace = pace;
  hardware::ArmEmulator emulator(settings);
  std::printf(
      "pneumatic arm lab: regulators on udp 127.0.0.1:%d, motion capture streaming to "
      "127.0.0.1:%d\nCtrl-C stops it.\n",
      emulator.command_port(), settings.mocap_port);
  std::fflush(stdout);
  emulator.run_until([] { return interrupted.load(); }, 1e9);
  return 0;
}

int check(const std::vector<std::string>& args) {
  const CommandLine line =
      CommandLine::parse(args, {"port", "baud", "pings", "steps", "udp-port", "mocap-port"}, {});
  require(line.positional.size() == 1, "expected `limb` or `arm`", "tendril robot check");
  const int pings = static_cast<int>(line.integer("pings", 50, 0, 100000));
  const int steps = static_cast<int>(line.integer("steps", 100, 1, 1000000));
  hardware::LinkCheck result;
  if (line.positional.front() == "limb") {
    require(line.has("port"), "needs --port (the limb's serial device)", "tendril robot check");
    hardware::LimbBridge bridge(
        std::make_unique<hardware::SerialTransport>(
            line.value("port", ""), static_cast<int>(line.integer("baud", 115200, 1, 4000000))),
        {});
    result = hardware::check_limb(bridge, pings, steps);
  } else {
    require(line.positional.front() == "arm", "expected `limb` or `arm`", "tendril robot check");
    auto commands = std::make_unique<hardware::UdpTransport>(
        "127.0.0.1", 0, "127.0.0.1", static_cast<int>(line.integer("udp-port", 51000, 1, 65535)));
    auto mocap = std::make_unique<hardware::UdpTransport>(
        "127.0.0.1", static_cast<int>(line.integer("mocap-port", 51001, 1, 65535)), "", 0);
    hardware::ArmBridge bridge(std::move(commands), std::move(mocap), {}, 10);
    result = hardware::check_arm(bridge, pings, steps);
  }
  std::fputs(result.report().c_str(), stdout);
  return 0;
}

int deploy(const std::vector<std::string>& args) {
#ifdef TENDRIL_WITH_RL
  const CommandLine line =
      CommandLine::parse(args, {"episodes", "steps", "seed", "csv", "epsilon"}, {"best", "filter"});
  require(line.positional.size() == 1, "expected one run directory", "tendril robot deploy");
  RunPolicy run = open_run_policy(line.positional.front(), line.has("best"), line.overrides);
  Rng rng(line.unsigned_integer("seed", 0));
  std::function<Action(const Observation&)> actor = [&](const Observation& o) {
    return run.policy->act(o, true, rng);
  };
#ifdef TENDRIL_WITH_SAFETY
  std::unique_ptr<safety::SafetyCritic> critic;
  std::unique_ptr<safety::SafetyFilter> filter;
  if (line.has("filter")) {
    critic = safety::load_safety_critic(std::filesystem::path(line.positional.front()) /
                                        "safety.critic");
    filter = std::make_unique<safety::SafetyFilter>(actor, *critic,
                                                    std::stod(line.value("epsilon", "0")));
    actor = [&](const Observation& o) { return filter->act(o); };
  }
#else
  require(!line.has("filter"), "this build has no safety layer", "--filter");
#endif
  hardware::DeployOptions options;
  options.episodes = static_cast<int>(line.integer("episodes", 1, 1, 1000000));
  options.max_steps = static_cast<int>(line.integer("steps", 0, 0, 100000000));
  options.seed = line.unsigned_integer("seed", 0);
  options.csv = line.value("csv", "");
  options.stop = &interrupted;
  catch_signals();
  const hardware::DeployResult result = hardware::deploy(*run.env, actor, options);
  std::printf("%d episode(s), %d steps%s\n", result.episodes, result.steps,
              result.stopped ? " (stopped by a signal)" : "");
  for (size_t k = 0; k < result.returns.size(); ++k) {
    std::printf("episode %zu: return %.6g\n", k, result.returns[k]);
  }
#ifdef TENDRIL_WITH_SAFETY
  if (filter) {
    std::printf("safety filter: %lld interventions in %lld decisions\n",
                static_cast<long long>(filter->interventions()),
                static_cast<long long>(filter->decisions()));
  }
#endif
  if (!result.fault.empty()) {
    std::fprintf(stderr, "stopped by a fault (the robot was commanded safe): %s\n",
                 result.fault.c_str());
    return 1;
  }
  return 0;
#else
  (void)args;
  throw Error("this build has no rl layer", "tendril robot deploy");
#endif
}

}  // namespace

int robot_command(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "emulate") return emulate(rest);
  if (args[0] == "check") return check(rest);
  if (args[0] == "deploy") return deploy(rest);
  std::fputs(kUsage, stderr);
  return 2;
}

}  // namespace tendril::apps
