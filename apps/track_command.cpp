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
#include "tendril/control/tracking_policy.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/runner/path_pushes.hpp"
#include "tendril/envs/runner/tracking_record.hpp"
#include "tendril/envs/sma_limb/policy_tracking_controller.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"
#ifdef TENDRIL_WITH_RL
#include "run_policy.hpp"
#endif

namespace tendril::apps {

namespace {

void write_run(std::ofstream& out, const std::filesystem::path& file, const std::string& pattern,
               const envs::TrackingRun& run, bool append) {
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
  std::function<std::shared_ptr<control::TrackingController>()> make_controller = [] {
    return std::make_shared<control::PidController>();
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
      return std::make_shared<envs::sma_limb::PolicyTrackingController>(policy, options,
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
    // Each reading filtered as the training data (StateFilter, thesis eqs. 4.5 and 4.7).
    const control::TrackingPolicy policy(
        *env, make_controller(), control::WaypointFollower(control::reference_pattern(pattern)));
    // Seed 001 §5.2.2 (a): a shove at 1/4 and 3/4 of the path, here along +x for 0.2 s.
    std::vector<envs::RunObserver*> observers;
    std::optional<envs::PathPushes> pushes;
    if (push_n > 0.0) {
      const int points = static_cast<int>(policy.follower().points().cols());
      pushes.emplace(policy, *env, Eigen::Vector2d(push_n, 0.0), 0.2,
                     std::vector<int>{points / 4, 3 * points / 4}, max_steps);
      observers.push_back(&*pushes);
    }
    const envs::TrackingRun run = envs::track_path(policy, *env, max_steps, seed, observers);
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
