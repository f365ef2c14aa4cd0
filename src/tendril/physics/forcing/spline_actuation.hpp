#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <vector>

#include "tendril/physics/forcing/cubic_spline.hpp"
#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// Muscle actuation of the Elastica RL arm (Naughton et al. 2021, "Arm actuation model"): in
// each active material direction m (d1 normal, d2 binormal, d3 twist) a torque profile
// A_m(s) = α_m β_m(s), β_m the not-a-knot cubic spline through the control points, with both
// ends of the arm pinned at zero, evaluated at each element's distal arc length and applied as
// that element's material-frame couple c_m.
struct SplineActuationSpec {
  int control_points = 6;  // per active direction
  // Control-point positions as fractions of the rest length, strictly inside (0, 1). Empty:
  // equidistant, s_j = j / (control_points + 1).
  std::vector<double> positions;
  std::array<bool, 3> directions{true, true, false};  // normal, binormal, twist
  double max_torque = 75.0;                           // α_m, N·m
  // Largest change of a control point per physics step (cases 3–4 use 0.01); ∞: none.
  double max_change_per_step = std::numeric_limits<double>::infinity();
  // How A(s) enters the elements. false (SPEC M2, the rate-limited cases of the paper's code):
  // element i's couple is A(s_i), an external distributed couple whose total grows with the
  // number of elements. true: A(s_i) acts across the joint before element i, +A on element i
  // and −A on element i − 1 — an internal active bending moment, independent of the mesh.
  bool paired = false;

  int active_directions() const { return directions[0] + directions[1] + directions[2]; }
  int action_size() const { return control_points * active_directions(); }
};

class SplineActuation final : public RodPart {
 public:
  explicit SplineActuation(SplineActuationSpec spec);

  // Material-frame couples: their derivatives vanish.
  uint32_t stages() const override { return kStartStep | kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void start_step(const RodModel& model, RodState& state, double step) override;
  void add_loads(const RodModel& model, RodState& state) override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  // Targets in [−1, 1], active directions in order (normal, binormal, twist), each
  // `control_points` long. The current control points follow them, rate-limited per step.
  void set_targets(const Eigen::VectorXd& targets);
  const Eigen::VectorXd& current() const { return current_; }
  const SplineActuationSpec& spec() const { return spec_; }
  // Couples of the current control points (3 × n, material frame, N·m).
  const Vectors& couples() const { return couples_; }

 private:
  void update_couples();

  SplineActuationSpec spec_;
  Eigen::MatrixXd weights_;  // elements × control points (ends pinned at 0, so left out)
  Eigen::VectorXd targets_, current_;
  Eigen::VectorXd profile_;  // A_m at the elements' distal ends, N·m
  Vectors couples_;
};

}  // namespace tendril::physics
