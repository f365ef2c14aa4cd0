#pragma once

#include <Eigen/Core>

#include "tendril/envs/learned/dynamics_model.hpp"
#include "tendril/envs/tendon_arm/arm_spec.hpp"

namespace tendril::envs::tendon_arm {

// A torch-free stand-in for a learned model of the arm, asked for by name (`model:
// constant_curvature`) so that TendonArm/LearnedReach-v0 runs, and is tested, without the
// dynamics layer. Not the arm: no gravity, no rod dynamics. The tip approaches, at first order,
// the constant-curvature tip (Webster & Jones 2010) of the tensions held:
//   x_{t+1} = x_t + β (x_cc(u_t) − x_t),   β = 1 − e^{−Δt/τ},  τ = 0.25 s,
// where the tendons' couple m = Σ_k T_k r ê_k (ê_k the lab direction of tendon k) bends the arm
// to κ = |m| / (E I) towards m, and x_cc = rest + L ((1 − cos θ)/θ m̂ + (1 − sin θ/θ) ẑ) with
// θ = κ L: the arc's tip, relative to the straight arm hanging at `rest`. States in m, inputs N.
class ConstantCurvatureModel final : public DynamicsModel {
 public:
  static constexpr double kLag = 0.25;  // s
  static constexpr const char* kName = "constant_curvature";

  ConstantCurvatureModel(const ArmSpec& spec, const Eigen::Vector3d& rest);

  // x_cc for constant tensions (N).
  Eigen::Vector3d steady_tip(const Eigen::VectorXd& tensions) const;

  int state_dim() const override { return 3; }
  int input_dim() const override { return spec_.tendons; }
  int window_length() const override { return 1; }
  double sample_period() const override { return spec_.control_period; }
  void predict(const BatchMatrix& windows, BatchMatrix& next_states) override;

 private:
  ArmSpec spec_;
  Eigen::Vector3d rest_;
  double beta_;
};

}  // namespace tendril::envs::tendon_arm
