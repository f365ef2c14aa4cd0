#pragma once

#include <memory>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/envs/env_description.hpp"
#include "tendril/envs/tendon_arm/arm_spec.hpp"
#include "tendril/physics/forcing/tendons.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::envs::tendon_arm {

// TendonArm/Robot-v0: a tendon-driven continuum arm as a robot — the inputs and outputs its
// hardware has, nothing of a task — with its twin behind it: a Cosserat rod clamped at the base
// and hanging under gravity, bent by pull-only tendons (physics::Tendons, Rucker & Webster 2011).
// Parameters: ArmSpec (arm_spec.hpp).
//
//   action       the tendon tensions, N, tendon k at 360° k / tendons from +x about the arm's
//                axis; Box [0, max_tension_n] (6 N). The motor drivers clamp whatever arrives to
//                that range (a tendon cannot push); a wrong size or a non-finite value is an Error.
//   observation  the tip position, m, lab frame (origin at the clamped base, z up; the arm hangs
//                to (0, 0, −0.30) at rest), as a tracker on the tip measures it; then each
//                tendon's travel, m (how far its motor has reeled it in from the unloaded straight
//                arm's tendon length: negative when the arm bends away from it, −0.8 mm at rest,
//                where the arm's weight stretches it), as the spool encoders measure it. 3 +
//                tendons values.
//   step         holds the tensions for control_period_s (0.1 s: 500 rod steps of 0.2 ms).
//   reset        the arm hanging still, tendons slack; the twin has no noise, so every reset is
//                the same state whatever the seed.
//   reward       0; terminated only if the rod's state became non-finite (info "nan" = 1).
// Info: "time_s" (since the reset), "nan".
class RobotEnv : public Env {
 public:
  static constexpr const char* kId = "TendonArm/Robot-v0";
  // Registered time limit: 60 s of control periods; data collection sets its own.
  static constexpr int64_t kTrialSteps = 600;
  static std::unique_ptr<Env> create(const Config& params);
  // The environment in words, for `tendril list envs --describe` (env_description.hpp).
  static EnvDescription description();
  // The tip at rest of the default arm (ArmSpec's defaults), m: hanging straight, stretched by
  // its own weight; a learned model's episodes start here unless told otherwise.
  static inline const Eigen::Vector3d kDefaultRest{0.0, 0.0, -0.300822};

  explicit RobotEnv(const ArmSpec& spec);

  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The arm's centreline and radius, its tendons' paths, its tip, the tensions.
  bool describe_scene(Scene& scene) const override;

  const ArmSpec& spec() const { return spec_; }
  const physics::Rod& rod() const { return rod_; }
  const physics::Tendons& tendons() const { return *tendons_; }
  double time() const { return rod_.time() - rest_time_; }

 private:
  Observation observe() const;

  ArmSpec spec_;
  physics::Rod rod_;
  physics::Tendons* tendons_;
  Snapshot rest_;  // the rod hanging still, as every reset begins
  double rest_time_ = 0.0;
  Eigen::VectorXd tensions_;
  Space observation_space_, action_space_;
  Observation last_observation_;
  Info info_;
};

}  // namespace tendril::envs::tendon_arm
