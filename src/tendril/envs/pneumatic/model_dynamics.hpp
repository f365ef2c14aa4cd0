#pragma once

#include <memory>

#include "tendril/core/rng.hpp"
#include "tendril/envs/learned/dynamics_model.hpp"
#include "tendril/envs/learned/history_windows.hpp"
#include "tendril/envs/pneumatic/arm_dynamics.hpp"

namespace tendril::envs::pneumatic {

// ArmDynamics over a learned model of the arm (seed 002 eq. (1): x_{t+1} = F(x_t, x_{t−1}, τ_t,
// τ_{t−1}, τ_{t−2}), run recursively on its own predictions, §III-C): the model's window of
// [tips (mm), pressures (bar)] rows is this source's whole state. A reset fills every row with
// the rest tips and vented chambers (the arm hanging still before the episode's first
// command), so a deterministic model starts every episode alike — unless `rest_jitter_mm` is
// positive: then each reset moves every rest coordinate by N(0, rest_jitter_mm²), from a stream
// a seeded reset restarts ("different trajectories can be obtained, even when executing the
// policy in the deterministic mode, by changing the initial conditions of the dynamics model",
// seed 002 §IV-B). `initial_offset_mm` (also off by default) moves each module's rest tip by
// an offset drawn uniformly from the ball of that radius, from the same stream after the
// jitter: the twin's resting drift moves the hanging arm between trials by up to its cap
// (40 mm at module 3, docs/results/pneumatic_arm.md), and Fig. 7's caption reports the policy
// run "even with different initial conditions" of the model.
class ModelDynamics final : public ArmDynamics {
 public:
  // Raises Error unless the model maps 9 tips and 9 pressures to 9 tips, `rest_mm` is finite
  // and the jitter and offset are finite and non-negative.
  ModelDynamics(std::shared_ptr<DynamicsModel> model, const TipVector& rest_mm,
                double rest_jitter_mm = 0.0, double initial_offset_mm = 0.0);

  TipVector reset(std::optional<uint64_t> seed) override;
  TipVector step(const ChamberVector& pressures_bar) override;
  bool finite() const override { return finite_; }
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The predicted arm as the polyline base → module tips and a sphere per tip (lab frame, m).
  void describe_scene(Scene& scene) const override;

  // The model fed the robot's real history (seed 002 §IV-C, Fig. 5: "the dynamics model took
  // feedback directly from the soft arm", X = [x_t, x_{t−1}]), for GPRCA's motor error:
  // reset_to fills the window with measured tips at vented chambers; predict_next returns
  // x̂_{t+1} for pressures held from now, without advancing; follow then appends the measured
  // x_{t+1} in place of the prediction.
  void reset_to(const TipVector& measured_mm);
  TipVector predict_next(const ChamberVector& pressures_bar);
  void follow(const TipVector& measured_mm);

  const TipVector& rest() const { return rest_; }
  const HistoryWindows& windows() const { return windows_; }

 private:
  std::shared_ptr<DynamicsModel> model_;
  TipVector rest_;
  HistoryWindows windows_;
  BatchMatrix inputs_, next_;
  TipVector tips_;
  bool finite_ = true;
  double rest_jitter_mm_;
  double initial_offset_mm_;
  Rng jitter_rng_;
};

}  // namespace tendril::envs::pneumatic
