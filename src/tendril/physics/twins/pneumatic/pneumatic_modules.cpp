#include "tendril/physics/twins/pneumatic/pneumatic_modules.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/physics/forcing/active_strain.hpp"

namespace tendril::physics::pneumatic {

void ModuleActuationSpec::validate() const {
  const char* where = "ModuleActuationSpec";
  require(elements_per_module >= 1, "elements_per_module must be at least 1", where);
  require(std::isfinite(module_length) && module_length > 0.0,
          "module_length must be finite and positive", where);
  require(std::isfinite(bend_per_bar) && bend_per_bar >= 0.0,
          "bend_per_bar must be finite and non-negative", where);
  require(std::isfinite(extension_per_bar) && extension_per_bar >= 0.0,
          "extension_per_bar must be finite and non-negative", where);
  for (double angle : chamber_angles) {
    require(std::isfinite(angle), "chamber_angles must be finite", where);
  }
  require(gains.allFinite() && (gains.array() >= 0.0).all(),
          "chamber gains must be finite and non-negative", where);
  require(std::isfinite(hysteresis_width_bar) && hysteresis_width_bar >= 0.0,
          "hysteresis_width_bar must be finite and non-negative", where);
  regulators.validate();
}

namespace {

const ModuleActuationSpec& validated(const ModuleActuationSpec& spec) {
  spec.validate();
  return spec;
}

}  // namespace

PneumaticModules::PneumaticModules(const ModuleActuationSpec& spec)
    : spec_(validated(spec)), regulators_(spec.regulators), hysteresis_(spec.hysteresis_width_bar) {
  const double per_bar = spec_.bend_per_bar / spec_.module_length;
  for (int k = 0; k < kChambers; ++k) {
    // r̂ × d3 for r̂ = (cos θ, sin θ, 0): an extending chamber curves the module away from it.
    const double angle = spec_.chamber_angles[k];
    curvature_per_bar_.col(k) = per_bar * Eigen::Vector2d(std::sin(angle), -std::cos(angle));
  }
}

void PneumaticModules::attach(const RodModel& model, const RodState&) {
  const int expected = kModules * spec_.elements_per_module;
  if (model.n_elements != expected) {
    throw Error("the rod has " + std::to_string(model.n_elements) + " elements; " +
                    std::to_string(kModules) + " modules of " +
                    std::to_string(spec_.elements_per_module) + " need " + std::to_string(expected),
                "PneumaticModules");
  }
  stretch_ = Vectors::Zero(3, model.n_elements);
  curvature_ = Vectors::Zero(3, model.n_voronoi());
  loads_.resize(model);
}

void PneumaticModules::vent() {
  regulators_.reset();
  hysteresis_.reset();
}

void PneumaticModules::start_step(const RodModel&, RodState&, double step) {
  regulators_.advance(step);
  const ChamberVector& effective = hysteresis_.update(regulators_.pressures());

  Eigen::Matrix<double, 2, kModules> module_curvature = bias_;
  Eigen::Matrix<double, 1, kModules> module_stretch;
  for (int m = 0; m < kModules; ++m) {
    double sum = 0.0;
    for (int c = 0; c < kChambersPerModule; ++c) {
      const int k = chamber_index(m, c);
      const double y = module_gains_[m] * spec_.gains[k] * effective[k];
      sum += y;
      module_curvature.col(m) += y * curvature_per_bar_.col(k);
    }
    module_stretch[m] = spec_.extension_per_bar * sum / kChambersPerModule;
  }

  const int per_module = spec_.elements_per_module;
  double* stretch = stretch_.row(2).data();
  double* curvature[2] = {curvature_.row(0).data(), curvature_.row(1).data()};
  for (int m = 0; m < kModules; ++m) {
    const int first = m * per_module, last = first + per_module;  // elements [first, last)
    for (int i = first; i < last; ++i) stretch[i] = module_stretch[m];
    // Voronoi point j joins elements j and j + 1: inside the module for j < last − 1; the one
    // on the joint with the next module takes the mean of both modules' curvatures.
    for (int r = 0; r < 2; ++r) {
      for (int j = first; j < last - 1; ++j) curvature[r][j] = module_curvature(r, m);
      if (m + 1 < kModules) {
        curvature[r][last - 1] = 0.5 * (module_curvature(r, m) + module_curvature(r, m + 1));
      }
    }
  }
}

void PneumaticModules::add_loads(const RodModel& model, RodState& state) {
  loads_.add(model, state, stretch_, curvature_);
}

void PneumaticModules::add_load_derivatives(const RodModel& model, const RodState& state,
                                            RodJacobian& jacobian) const {
  loads_.add_derivatives(model, state, jacobian);
}

void PneumaticModules::set_module_gains(const Eigen::Matrix<double, 1, kModules>& gains) {
  require(gains.allFinite() && (gains.array() >= 0.0).all(),
          "module gains must be finite and non-negative", "PneumaticModules");
  module_gains_ = gains;
}

void PneumaticModules::save_state(SnapshotWriter& out) const {
  out.section("PneumaticModules");
  regulators_.save_state(out);
  hysteresis_.save_state(out);
  out.put_matrix(bias_);
  out.put_matrix(module_gains_);
}

void PneumaticModules::load_state(SnapshotReader& in) {
  in.section("PneumaticModules");
  PressureRegulators regulators = regulators_;
  PlayHysteresis hysteresis = hysteresis_;
  Eigen::Matrix<double, 2, kModules> bias;
  Eigen::Matrix<double, 1, kModules> module_gains;
  regulators.load_state(in);
  hysteresis.load_state(in);
  in.get_matrix(bias);
  in.get_matrix(module_gains);
  regulators_ = regulators;
  hysteresis_ = hysteresis;
  bias_ = bias;
  module_gains_ = module_gains;
}

}  // namespace tendril::physics::pneumatic
