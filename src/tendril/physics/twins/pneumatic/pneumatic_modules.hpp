#pragma once

#include <Eigen/Core>
#include <array>

#include "tendril/physics/forcing/active_strain.hpp"
#include "tendril/physics/rod/rod_part.hpp"
#include "tendril/physics/twins/pneumatic/chambers.hpp"
#include "tendril/physics/twins/pneumatic/play_hysteresis.hpp"
#include "tendril/physics/twins/pneumatic/pressure_regulators.hpp"

namespace tendril::physics::pneumatic {

// How chamber pressures strain the modules of a rod made of kModules equal modules.
struct ModuleActuationSpec {
  int elements_per_module = 6;
  double module_length = 0.598 / 3.0;  // m, rest length of one module
  // Free bending angle of a module (no gravity) per bar in one chamber, rad.
  double bend_per_bar = 30.0 * 3.14159265358979323846 / 180.0;
  // Free axial strain of a module per bar of mean chamber pressure.
  double extension_per_bar = 0.10;
  // Angle of each chamber's centre in its module's cross-section, material frame, from d1
  // toward d2 (rad). Default: chamber c of every module at c · 120°.
  std::array<double, kChambers> chamber_angles{0.0, 2.0943951023931957, 4.1887902047863905,
                                               0.0, 2.0943951023931957, 4.1887902047863905,
                                               0.0, 2.0943951023931957, 4.1887902047863905};
  // Per-chamber gain on the strain a pressure produces (manufacturing imbalance; 1 = nominal).
  ChamberVector gains = ChamberVector::Ones();
  RegulatorSpec regulators;
  double hysteresis_width_bar = 0.0;  // PlayHysteresis width; 0 = none

  void validate() const;
};

// The chambers of all modules as one rod part (seed 002 §III-A: "one chamber, or a pair of
// chambers, pressurised → the module bends … all three at equal pressure → the arm extends").
//
// Each chamber is an extending fluidic muscle at 120° intervals around its module's axis. Its
// pressure, through the regulators' lag and the material's hysteresis, is an effective
// pressure y_k; a module's chambers then impose a spontaneous (active) strain on every element
// of the module (physics/forcing/active_strain.hpp):
//   axial strain   δσ₃ = extension_per_bar · G_m (Σ_k g_k y_k) / 3
//   curvature      δκ  = (bend_per_bar / L_m) · G_m Σ_k g_k y_k · (r̂_k × d3) + drift bias
// with r̂_k the chamber's unit position in the cross-section (material frame), g_k the chamber's
// gain and G_m the module's gain of the trial (set_module_gains). An extending
// chamber lengthens its side of the module, so a single chamber bends the module away from
// itself, in the plane through the axis and the chamber; three equal pressures cancel in δκ
// and only extend. At a Voronoi point on the joint between two modules the mean of both
// modules' curvatures applies. The loads are exactly those of shifting the rest strains, so
// they are self-equilibrated and do not depend on the number of elements.
//
// The regulators advance once per rod step (kStartStep), by the step's length.
class PneumaticModules final : public RodPart {
 public:
  explicit PneumaticModules(const ModuleActuationSpec& spec);

  uint32_t stages() const override { return kStartStep | kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void start_step(const RodModel& model, RodState& state, double step) override;
  void add_loads(const RodModel& model, RodState& state) override;
  void add_load_derivatives(const RodModel& model, const RodState& state,
                            RodJacobian& jacobian) const override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  // Pressure commands, bar; clamped by the regulators (range, ceiling, damage).
  void set_commands(const ChamberVector& commands_bar) { regulators_.set_commands(commands_bar); }
  // Vents every chamber and clears the hysteresis (the start of a trial).
  void vent();
  const PressureRegulators& regulators() const { return regulators_; }
  const ChamberVector& effective_pressures() const { return hysteresis_.output(); }

  // Resting-position drift: an extra curvature of each module (material frame, components
  // along d1 and d2, 1/m), set between trials.
  void set_curvature_bias(const Eigen::Matrix<double, 2, kModules>& bias) { bias_ = bias; }
  const Eigen::Matrix<double, 2, kModules>& curvature_bias() const { return bias_; }
  // Elasticity of the day: a factor on every strain a module's chambers produce (1 = nominal),
  // set between trials.
  void set_module_gains(const Eigen::Matrix<double, 1, kModules>& gains);
  const Eigen::Matrix<double, 1, kModules>& module_gains() const { return module_gains_; }

  // Material-frame direction (d1, d2) of the curvature one chamber produces per bar, 1/m.
  Eigen::Vector2d curvature_per_bar(int chamber) const { return curvature_per_bar_.col(chamber); }

 private:
  ModuleActuationSpec spec_;
  PressureRegulators regulators_;
  PlayHysteresis hysteresis_;
  Eigen::Matrix<double, 2, kModules> bias_ = Eigen::Matrix<double, 2, kModules>::Zero();
  Eigen::Matrix<double, 1, kModules> module_gains_ = Eigen::Matrix<double, 1, kModules>::Ones();
  Eigen::Matrix<double, 2, kChambers> curvature_per_bar_;  // set at attach
  Vectors stretch_, curvature_;  // per element / per Voronoi point, reused every step
  ActiveStrainLoads loads_;
};

}  // namespace tendril::physics::pneumatic
