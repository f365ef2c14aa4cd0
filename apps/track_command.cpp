// `tendril track`: seed 001's tracking experiments (thesis §5.2, Tables 5.4–5.5) on the SMA limb
// behind its robot interface — the twin, or a limb over the bridge (--set env.params.backend=
// bridge) — with the waypoint follower and the PID baseline or a policy trained in
// SmaLimb/LearnedReach-v0 (--policy RUN), on the calibration the policy's model was fitted with.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "limb_deployment.hpp"
#include "tendril/control/reference_patterns.hpp"
#include "tendril/control/state_filter.hpp"
#include "tendril/control/tracking_loop.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/pushable_robot.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/policy_tracking_controller.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"
#ifdef TENDRIL_WITH_RL
#include "run_policy.hpp"
#endif

namespace tendril::apps {

namespace {

// The limb as a deployed controller sees it: each reading passed through the same state
// estimate as the training data (control::StateFilter, thesis eqs. 4.5 and 4.7).
class RobotLimb final : public control::TrackedLimb {
 public:
  RobotLimb(Env& robot, uint64_t seed) : robot_(robot), seed_(seed) {}

  control::LimbState reset() override {
    filter_.reset();
    return state(robot_.reset(seed_));
  }
  control::LimbState apply(const Eigen::Vector2d& throttles) override {
    const Step step = robot_.step(throttles.cast<float>());
    require(!step.terminated, "the limb's state became non-finite", "tendril track");
    return state(step.observation);
  }

 private:
  control::LimbState state(const Observation& reading) {
    const Eigen::Vector2d angles(reading[0], reading[1]);
    const Eigen::Vector4d x = filter_.update(reading[2], angles);
    return control::LimbState{.time_s = reading[2], .angles = x.head<2>(), .rates = x.tail<2>()};
  }

  Env& robot_;  // SmaLimb/Robot-v0, on the bridge inside its HardwareInfo wrapper
  uint64_t seed_;
  control::StateFilter filter_;
};

void write_run(std::ofstream& out, const std::filesystem::path& file, const std::string& pattern,
               const control::TrackingRun& run, bool append) {
  if (!append) out << "pattern,step,time_s,theta_x,theta_y,goal_x,goal_y,u_x,u_y\n";
  for (Eigen::Index k = 0; k < run.angles.cols(); ++k) {
    out << pattern << ',' << k << ',' << run.times[k] << ',' << run.angles(0, k) << ','
        << run.angles(1, k) << ',' << run.goals(0, k) << ',' << run.goals(1, k) << ','
        << run.throttles(0, k) << ',' << run.throttles(1, k) << '\n';
  }
  out.flush();
  require(out.good(), "writing failed (disk full?)", file.string());
}

}  // namespace

int track_command(const Arguments& line) {
  const std::string which = line.positional.empty() ? "all" : line.positional[0];
  std::vector<std::string> patterns = control::reference_pattern_names();
  if (which != "all") patterns = {which};
  const std::string limb = line.value("limb", "stiff");
  const double tip_mass = line.number("tip-mass", 0.0, 0.0, 1.0);
  const double push_n = line.number("push", 0.0, 0.0, 100.0);
  const int max_steps = static_cast<int>(line.integer("steps", 3000, 1, 100000000));
  const uint64_t seed = line.unsigned_integer("seed", 0);
  const std::string out = line.value("output", "");
  require(!out.empty() ? !std::filesystem::exists(out) : true,
          "exists already; choose another file", out);

  // The controller: PID, or a trained policy that acts on the limb as on the learned model.
  std::function<std::unique_ptr<control::TrackingController>()> make_controller = [] {
    return std::make_unique<control::PidController>();
  };
  std::string controller_name = "PID (Kp 2, Ki 0.001, Kd 0.5)";
  // The policy's learned model names the calibration its data came from (LimbDeployment).
  std::optional<Config> trained_env_params;
  if (line.has("policy")) {
#ifdef TENDRIL_WITH_RL
    const RunPolicy run = open_run_policy(line.value("policy", ""), line.has("best"));
    trained_env_params = run.experiment.env.params;
    const auto options =
        envs::sma_limb::LearnedReachOptions::from_config(run.experiment.env.params);
    const bool deterministic = !line.has("stochastic");
    make_controller = [policy = run.policy, options, deterministic, seed] {
      return std::make_unique<envs::sma_limb::PolicyTrackingController>(policy, options,
                                                                        deterministic, seed);
    };
    controller_name = "the policy of " + run.source.string() +
                      (deterministic ? " (mean actions)" : " (sampled actions)");
#else
    throw Error("this program was built without the RL layer", "tendril track --policy");
#endif
  }
  const LimbDeployment deployment =
      limb_deployment(line, trained_env_params ? &*trained_env_params : nullptr, "track");
  std::printf(
      "%s on the %s limb (%s), calibration %s, tip mass %.3f kg%s\n", controller_name.c_str(),
      limb.c_str(), deployment.params.get_or<std::string>("backend", "twin").c_str(),
      deployment.calibration.c_str(), tip_mass, push_n > 0 ? ", pushes at 1/4 and 3/4" : "");
  std::ofstream out_file;
  if (!out.empty()) {
    out_file.open(out, std::ios::binary);
    require(out_file.good(), "cannot write", out);
  }
  std::printf("%-8s %8s %9s %10s\n", "pattern", "steps", "finished", "RMSE [deg]");
  bool first = true;
  for (const std::string& pattern : patterns) {
    Config params = deployment.params;
    char mass[32];
    std::snprintf(mass, sizeof mass, "%.17g", tip_mass);
    params.set("tip_mass", mass);
    params.set("seed", std::to_string(seed));
    auto env = envs::make(envs::sma_limb::SmaLimbEnv::kId, params);
    RobotLimb limb_under_control(*env, seed);
    control::WaypointFollower follower(control::reference_pattern(pattern));
    const std::unique_ptr<control::TrackingController> controller = make_controller();
    const int points = static_cast<int>(follower.points().cols());
    int pushes = 0;
    // Seed 001 §5.2.2 (a): a shove at 1/4 and 3/4 of the path, here along +x for 0.2 s.
    auto disturb = [&](int, const control::WaypointFollower& f) {
      if (push_n <= 0.0) return;
      const int due = pushes == 0 ? points / 4 : pushes == 1 ? 3 * points / 4 : points + 1;
      if (f.index() >= due) {
        auto* robot = envs::find_wrapper<envs::PushableRobot>(*env);
        require(robot != nullptr, "the robot cannot be pushed", "tendril track --push");
        robot->push_tip(push_n * Eigen::VectorXd::Unit(robot->push_dim(), 0), 0.2);
        ++pushes;
      }
    };
    const control::TrackingRun run =
        control::track(limb_under_control, *controller, follower, max_steps, disturb);
    if (std::isnan(run.rmse_deg)) {
      std::printf("%-8s %8ld %9s %s\n", pattern.c_str(), static_cast<long>(run.angles.cols()), "no",
                  "the path's first point was never reached");
    } else {
      std::printf("%-8s %8ld %9s %10.2f\n", pattern.c_str(), static_cast<long>(run.angles.cols()),
                  run.finished ? "yes" : "no", run.rmse_deg);
    }
    if (!out.empty()) write_run(out_file, out, pattern, run, !first);
    first = false;
  }
  if (!out.empty()) {
    out_file.close();
    require(!out_file.fail(), "writing failed (disk full?)", out);
    std::printf("wrote %s\n", out.c_str());
  }
  return 0;
}

}  // namespace tendril::apps
