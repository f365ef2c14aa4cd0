#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// Pull-only tendons of a tendon-driven continuum robot (Rucker & Webster 2011, "Statics and
// dynamics of continuum robots with general tendon routing and external loading", IEEE T-RO
// 27(6)), routed parallel to the centreline through guides at a fixed offset r in the material
// frame, anchored at the base and terminated at the tip.
//
// Cutting the rod anywhere, the tendon loads distal to the cut add up to the tendon's own tension
// there: a compression T along the tendon at offset r, i.e. a compression T along the centreline
// plus a bending couple T (t × r) on the distal part. The tendon and the rod form a
// self-equilibrated pair, so the part applies exactly these section resultants as internal loads:
//   - each element i is compressed by T: +T t_i on node i, −T t_i on node i + 1;
//   - across each joint j (between elements j and j + 1) the couple C_j = T t̄_j × r̄_j acts on
//     element j + 1 and −C_j on element j (lab frame; r̄ = r1 ē1 + r2 ē2 and t̄ with ē1, ē2, t̄ the
//     unit means of the two elements' d1, d2, d3).
// The moment is T |r| at every joint whatever the mesh, so a constant tension bends a straight,
// unshearable rod to the constant curvature κ = T |r| ε³ / (E I) (ε the dilatation; the discrete
// rod's bending couple is B κ / ε³) — the closed form of a tendon-driven continuum robot. All
// tendons together act through two resultants, Σ T_k and Σ T_k r_k, so the cost of a step does
// not grow with their number.
//
// The tension of tendon k follows the law T = max(0, T_k + K_k (l_k − l̂_k)) with l_k the tendon's
// length now and l̂_k at attach time: a prescribed tension (K = 0) or an elastic tendon such as an
// actuator coil whose pre-load T_k the owner sets between steps. A slack tendon (T = 0) exerts
// nothing: tendons only pull. The length of a tendon at offset r is that of its offset curve,
// l = Σ_i l_i − Σ_j D̂_j (r × κ_j)·d3 (the rod's current length, less r times the bending towards
// the tendon), exact for a constant curvature.
class Tendons final : public RodPart {
 public:
  // Offsets (material frame, m; the d3 component must be zero), one per tendon.
  explicit Tendons(std::vector<Eigen::Vector3d> offsets);

  uint32_t stages() const override { return kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void add_loads(const RodModel& model, RodState& state) override;
  // For an implicit step, the compression's change with the elements' directions at the last
  // step's tensions, T (I − t tᵀ)/l. Left out: the tensions' change with the tendons' lengths
  // (it couples every element to every other) and the couples' change with the relative
  // rotation of neighbouring frames; Newton's method takes those as a fixed-point iteration.
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  int count() const { return static_cast<int>(offsets_.size()); }
  const Eigen::Vector3d& offset(int tendon) const { return offsets_[tendon]; }

  // T = max(0, tension_at_rest_length + stiffness (l − l̂)); N and N/m, finite, stiffness ≥ 0.
  void set_tension_law(int tendon, double tension_at_rest_length, double stiffness);
  void set_tension(int tendon, double tension) { set_tension_law(tendon, tension, 0.0); }

  // Of the last step (the configuration at its middle, where loads are evaluated).
  double tension(int tendon) const { return tensions_[tendon]; }
  double path_length(int tendon) const { return path_lengths_[tendon]; }
  double rest_path_length(int tendon) const { return rest_path_lengths_[tendon]; }

  // The length of `tendon` in `state`, whose strains must be current (as after a step).
  double path_length(const RodState& state, int tendon) const;
  // Where `tendon` runs in `state` (lab frame, m), for drawing: one point per node, offset by
  // the average frame of the node's elements.
  Eigen::Matrix3Xd path(const RodState& state, int tendon) const;

 private:
  std::vector<Eigen::Vector3d> offsets_;
  std::vector<double> tensions_at_rest_, stiffnesses_;
  std::vector<double> tensions_, path_lengths_, rest_path_lengths_;
  Eigen::VectorXd joint_lengths_;  // D̂_j, m
};

}  // namespace tendril::physics
