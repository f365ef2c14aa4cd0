#pragma once

#include <Eigen/Core>

#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// The internal damping of the paper-era Elastica engine used by the soft-arm RL cases: per
// element a force ν v̄ l (v̄ the mean velocity of its two nodes, l its current length) shared
// half-and-half by its nodes, and a torque ν ω l, both opposing motion. ν in kg/(m·s); the arm
// uses ν = 30 (Table 6 of the Elastica RL paper). Explicitly integrated, it bounds the time
// step; an implicit step takes it with its exact derivatives.
class InternalDamping final : public RodPart {
 public:
  explicit InternalDamping(double coefficient);
  uint32_t stages() const override { return kLoads; }
  void add_loads(const RodModel& model, RodState& state) override;
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override;

  double coefficient() const { return coefficient_; }

 private:
  double coefficient_;
};

// Rayleigh damping f = −γ_t v and c = −γ_r ω per unit length. Position Verlet integrates it
// exactly over a step after the rest of the step: each rate decays as exp(−rate · dt), so it is
// unconditionally stable; rotational rates use the rest dilatation. An implicit step takes it
// as loads, −γ_t D_j v_j on node j (D_j its share of rest length) and −γ_r l̂_i ω_i on element
// i, with everything else. γ_t in kg/(m·s), γ_r in kg·m/s.
class AnalyticalLinearDamping final : public RodPart {
 public:
  AnalyticalLinearDamping(double translational, double rotational);
  uint32_t stages() const override { return kDampRates; }
  void attach(const RodModel& model, const RodState& state) override;
  void damp_rates(const RodModel& model, RodState& state) override;
  void add_damping_loads(const RodModel& model, RodState& state) override;
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override;

  // What damp_rates multiplies the rates by each step (after attach): per node, and per
  // element and material axis.
  const Eigen::VectorXd& velocity_factors() const { return velocity_factors_; }
  const Vectors& angular_factors() const { return angular_factors_; }

 private:
  double translational_, rotational_;
  Eigen::VectorXd velocity_factors_;      // per node
  Vectors angular_factors_;               // per element and material axis
  Eigen::VectorXd node_coefficients_;     // γ_t D_j, N·s/m
  Eigen::VectorXd element_coefficients_;  // γ_r l̂_i, N·m·s
};

}  // namespace tendril::physics
