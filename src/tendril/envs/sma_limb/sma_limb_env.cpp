#include "tendril/envs/sma_limb/sma_limb_env.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/sma_limb/bridge_limb_robot.hpp"
#include "tendril/envs/sma_limb/twin_limb_robot.hpp"

namespace tendril::envs::sma_limb {

namespace {

constexpr const char* kPwmKeys[4] = {"pwm_0", "pwm_1", "pwm_2", "pwm_3"};

}  // namespace

SmaLimbEnv::SmaLimbEnv(std::unique_ptr<LimbRobot> robot, LimbCalibration calibration, uint64_t seed)
    : robot_(std::move(robot)),
      calibration_(std::move(calibration)),
      // Bends reach ±180°; a reading's zero offset may add to that.
      observation_space_(
          Space::box(Eigen::Vector3f(-360.0f, -360.0f, 0.0f),
                     Eigen::Vector3f(360.0f, 360.0f, std::numeric_limits<float>::infinity()))),
      action_space_(
          Space::box(2, -static_cast<float>(kMaxThrottle), static_cast<float>(kMaxThrottle))),
      rng_(seed) {
  require(robot_ != nullptr, "needs a robot", kId);
  calibration_.validate(kId);
  info_.set("time_s", 0.0);
  info_.set("u_x", 0.0);
  info_.set("u_y", 0.0);
  for (const char* key : kPwmKeys) info_.set(key, 0.0);
  info_.set("cutoff", 0.0);
  info_.set(info_keys::kNan, 0.0);
}

std::unique_ptr<Env> SmaLimbEnv::create(const Config& params) {
  const std::string limb = params.get_or<std::string>("limb", "stiff");
  physics::SmaLimbSpec spec = physics::SmaLimbSpec::variant(limb);
  spec.tip_mass = params.get_or<double>("tip_mass", 0.0);
  if (params.has("integrator")) {
    try {
      spec.integrator = physics::parse_integrator(params.get<std::string>("integrator"));
    } catch (const Error& e) {
      throw Error(e.what_wrong(), params.source() + ": integrator");
    }
  }
  // An implicit twin's longest step between two readings (SmaLimbSpec::implicit_step, s).
  if (params.has("implicit_step")) {
    spec.implicit_step = params.get<double>("implicit_step");
    if (!(std::isfinite(spec.implicit_step) && spec.implicit_step > 0.0)) {
      throw Error("implicit_step must be finite and positive (s), got " +
                      std::to_string(spec.implicit_step),
                  params.where("implicit_step"));
    }
  }
  // The silicone's viscous loss (SmaLimbSpec::damping_rate, 1/s): the limb's own unless a
  // study of the twin's damping sets it (docs/results/learned_dynamics.md).
  if (params.has("damping_rate")) {
    spec.damping_rate = params.get<double>("damping_rate");
    if (!(std::isfinite(spec.damping_rate) && spec.damping_rate >= 0.0)) {
      throw Error("damping_rate must be finite and non-negative (1/s), got " +
                      std::to_string(spec.damping_rate),
                  params.where("damping_rate"));
    }
  }
  // How the coils' phase continues on a re-entered branch (physics::PhaseReentry): resume, the
  // twin's own, or continuous.
  if (params.has("phase_reentry")) {
    const std::string reentry = params.get<std::string>("phase_reentry");
    if (reentry != "resume" && reentry != "continuous") {
      throw Error("phase_reentry must be resume or continuous, got '" + reentry + "'",
                  params.where("phase_reentry"));
    }
    spec.actuator.coil.phase_reentry = reentry == "continuous" ? physics::PhaseReentry::kContinuous
                                                               : physics::PhaseReentry::kResume;
  }
  const uint64_t seed = params.get_or<uint64_t>("seed", 0);
  // Data sets, models, policies and critics all come from the calibrated limb (its PWM table,
  // its sensor's zero offsets removed). A limb built on the nominal table with raw readings is
  // another system to them — the twin at rest reads (−10°, −12°) — so the calibration is never
  // a default: a file, or `none` said on purpose (before a calibration, or to study one).
  if (!params.has("calibration")) {
    throw Error(
        "needs the limb's calibration: calibration: FILE (written by `tendril data calibrate`, "
        "e.g. configs/sma_limb/calibration_" +
            limb +
            ".yaml), or calibration: none for the nominal PWM table and the sensor's raw "
            "readings",
        params.where("calibration"));
  }
  const std::string file = params.get<std::string>("calibration");
  LimbCalibration calibration = LimbCalibration::nominal(limb);
  if (file != kUncalibrated) {
    calibration = LimbCalibration::load(file);
    if (calibration.limb != limb) {
      throw Error("calibration was made on limb '" + calibration.limb + "', not '" + limb + "'",
                  file);
    }
  }
  // The robot behind the interface: the twin, or the bridge to the firmware (a real limb or
  // the firmware in its emulator; `bridge:` names the link and the safety settings).
  const std::string backend = params.get_or<std::string>("backend", "twin");
  if (backend == "bridge") {
    return make_bridge_limb_env(params.child("bridge"), std::move(calibration), seed);
  }
  if (backend != "twin") {
    throw Error("backend must be twin or bridge, got '" + backend + "'", params.where("backend"));
  }
  spec.validate();
  return std::make_unique<SmaLimbEnv>(std::make_unique<TwinLimbRobot>(spec), std::move(calibration),
                                      seed);
}

Observation SmaLimbEnv::observe(const LimbSample& sample) {
  time_s_ = sample.time_s;
  angles_deg_ = sample.angles_deg - calibration_.zero_offset_deg;
  return Eigen::Vector3f(static_cast<float>(angles_deg_.x()), static_cast<float>(angles_deg_.y()),
                         static_cast<float>(time_s_));
}

Observation SmaLimbEnv::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  failed_ = false;
  info_.set(info_keys::kNan, 0.0);
  return observe(robot_->reset(rng_.next_u64()));
}

Step SmaLimbEnv::step(const Action& action) {
  check_action(action_space_, action, kId);
  Step result;
  if (failed_) {
    result.observation = observe({time_s_, angles_deg_ + calibration_.zero_offset_deg});
    result.terminated = true;
    result.info = info_;
    return result;
  }
  const double ux = std::clamp<double>(std::lround(action[0]), -kMaxThrottle, kMaxThrottle);
  const double uy = std::clamp<double>(std::lround(action[1]), -kMaxThrottle, kMaxThrottle);
  // The firmware acts on the reading it has: beyond 100° on either axis every coil stays off.
  const bool cutoff =
      std::abs(angles_deg_.x()) >= kCutoffDeg || std::abs(angles_deg_.y()) >= kCutoffDeg;
  const std::array<int, 4> pwm =
      cutoff ? std::array<int, 4>{0, 0, 0, 0} : calibration_.pwm_for(ux, uy);
  const LimbSample sample = robot_->command(pwm);
  info_.set("u_x", ux);
  info_.set("u_y", uy);
  for (int coil = 0; coil < 4; ++coil) info_.set(kPwmKeys[coil], pwm[coil]);
  info_.set("cutoff", cutoff ? 1.0 : 0.0);
  if (!sample.angles_deg.allFinite()) {
    failed_ = true;
    time_s_ = sample.time_s;
    result.observation = observe({time_s_, angles_deg_ + calibration_.zero_offset_deg});
    result.terminated = true;
    info_.set(info_keys::kNan, 1.0);
  } else {
    result.observation = observe(sample);
  }
  info_.set("time_s", time_s_);
  result.info = info_;
  return result;
}

void SmaLimbEnv::save_state(SnapshotWriter& out) const {
  out.section(kId);
  robot_->save_state(out);
  out.put(rng_);
  out.put_matrix(angles_deg_);
  out.put(time_s_);
  out.put(failed_);
  for (const auto& entry : info_.entries()) out.put(entry.second);
}

void SmaLimbEnv::load_state(SnapshotReader& in) {
  in.section(kId);
  load_all_or_nothing(*robot_, in, [&] {
    Rng rng = rng_;
    in.get(rng);
    Eigen::Vector2d angles = angles_deg_;
    in.get_matrix(angles);
    const double time = in.get_double();
    const bool failed = in.get_bool();
    Info info = info_;
    for (const auto& entry : info_.entries()) info.set(entry.first, in.get_double());
    rng_ = rng;
    angles_deg_ = angles;
    time_s_ = time;
    failed_ = failed;
    info_ = std::move(info);
  });
}

bool SmaLimbEnv::describe_scene(Scene& scene) const {
  if (!robot_->describe_scene(scene)) return false;
  scene.time = time_s_;
  scene.values.emplace_back("reading theta_x_deg", angles_deg_.x());
  scene.values.emplace_back("reading theta_y_deg", angles_deg_.y());
  return true;
}

void SmaLimbEnv::push_tip(const Eigen::VectorXd& force_n, double duration_s) {
  require(force_n.size() == 2, "a push on the limb has 2 components (x, y)", kId);
  require(force_n.allFinite() && std::isfinite(duration_s) && duration_s >= 0.0,
          "push force and duration must be finite, duration >= 0", kId);
  robot_->push(Eigen::Vector2d(force_n), duration_s);
}

EnvDescription SmaLimbEnv::description() {
  return {
      .observation = {{"bend reading θx, zero offset removed", "°"},
                      {"bend reading θy, zero offset removed", "°"},
                      {"time stamp of the reading since reset", "s"}},
      .action = {{"throttle u_x, rounded to a whole level; + drives the +x coil, − the −x coil",
                  "1"},
                 {"throttle u_y, likewise for the y coils", "1"}},
      .reward = "0 (the robot has no task)",
      .episode_end =
          "terminated only when a simulated limb's state becomes non-finite; no time "
          "limit (a task or a TimeLimit decides)",
      .parameters = {{"limb", "", "stiff or soft (seed 001's two limbs)"},
                     {"tip_mass", "kg", "mass hung at the tip"},
                     {"integrator", "", "the twin's rod integrator; default the limb's own", true},
                     {"implicit_step", "s",
                      "an implicit twin's longest rod step between two readings; default 0.005",
                      true},
                     {"damping_rate", "1/s",
                      "the twin's viscous loss, every rate decaying at it; default the limb's own "
                      "(15)",
                      true},
                     {"phase_reentry", "",
                      "resume (the twin's own: a coil's phase branch re-entered at another "
                      "temperature jumps) or continuous (it never moves against the temperature)",
                      true},
                     {"seed", "", "random stream of the first reset without a seed"},
                     {"calibration", "",
                      "required: a file of `tendril data calibrate`, or none "
                      "(the nominal PWM table, raw readings)"},
                     {"backend", "", "twin, or bridge to the firmware"},
                     {"bridge.*", "",
                      "with backend: bridge, the link and safety settings "
                      "(docs/hardware.md)",
                      true}},
  };
}

}  // namespace tendril::envs::sma_limb
