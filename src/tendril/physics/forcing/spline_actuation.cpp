#include "tendril/physics/forcing/spline_actuation.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

SplineActuation::SplineActuation(SplineActuationSpec spec) : spec_(std::move(spec)) {
  const char* who = "SplineActuation";
  require(spec_.control_points >= 1, "control_points must be at least 1", who);
  require(spec_.active_directions() >= 1, "at least one direction must be active", who);
  require(std::isfinite(spec_.max_torque) && spec_.max_torque > 0.0,
          "max_torque must be finite and positive", who);
  require(spec_.max_change_per_step > 0.0, "max_change_per_step must be positive", who);
  if (spec_.positions.empty()) {
    for (int j = 1; j <= spec_.control_points; ++j) {
      spec_.positions.push_back(static_cast<double>(j) / (spec_.control_points + 1));
    }
  }
  require(static_cast<int>(spec_.positions.size()) == spec_.control_points,
          "positions must list one fraction per control point", who);
  for (std::size_t j = 0; j < spec_.positions.size(); ++j) {
    require(spec_.positions[j] > 0.0 && spec_.positions[j] < 1.0 &&
                (j == 0 || spec_.positions[j] > spec_.positions[j - 1]),
            "positions must be strictly increasing inside (0, 1)", who);
  }
  targets_ = Eigen::VectorXd::Zero(spec_.action_size());
  current_ = targets_;
}

void SplineActuation::attach(const RodModel& model, const RodState&) {
  const int n = model.n_elements;
  const double length = model.rest_lengths.sum();
  const int cp = spec_.control_points;
  Eigen::VectorXd knots(cp + 2);
  knots[0] = 0.0;
  for (int j = 0; j < cp; ++j) knots[j + 1] = spec_.positions[j] * length;
  knots[cp + 1] = length;
  Eigen::VectorXd distal(n);  // arc length at each element's far end
  double arc = 0.0;
  for (int i = 0; i < n; ++i) distal[i] = (arc += model.rest_lengths[i]);
  const CubicSplineMap spline(knots, distal);
  weights_ = spline.weights().middleCols(1, cp);  // the pinned end values are zero
  couples_ = Vectors::Zero(3, n);
  profile_ = Eigen::VectorXd::Zero(n);
}

void SplineActuation::set_targets(const Eigen::VectorXd& targets) {
  // Checked without building messages on the hot path: this runs once per RL step.
  if (targets.size() != targets_.size()) {
    throw Error("expected " + std::to_string(targets_.size()) + " control-point targets, got " +
                    std::to_string(targets.size()),
                "SplineActuation");
  }
  if (!targets.allFinite()) throw Error("control-point targets must be finite", "SplineActuation");
  targets_ = targets.cwiseMax(-1.0).cwiseMin(1.0);
  if (!std::isfinite(spec_.max_change_per_step)) {
    current_ = targets_;
    update_couples();
  }
}

void SplineActuation::update_couples() {
  const int cp = spec_.control_points;
  const Eigen::Index n = couples_.cols();
  int block = 0;
  for (int m = 0; m < 3; ++m) {
    if (!spec_.directions[m]) continue;
    profile_.noalias() = weights_ * current_.segment(block * cp, cp);
    profile_ *= spec_.max_torque;
    if (spec_.paired) {
      // Element i gets +A(s_i) and element i − 1 gets −A(s_i) for i ≥ 1: equal and opposite
      // couples across each joint between elements.
      couples_.row(m).setZero();
      couples_.row(m).tail(n - 1) += profile_.tail(n - 1).transpose();
      couples_.row(m).head(n - 1) -= profile_.tail(n - 1).transpose();
    } else {
      couples_.row(m) = profile_.transpose();
    }
    ++block;
  }
}

void SplineActuation::start_step(const RodModel&, RodState&, double) {
  if (std::isfinite(spec_.max_change_per_step) && current_ != targets_) {
    const double limit = spec_.max_change_per_step;
    current_ += (targets_ - current_).cwiseMax(-limit).cwiseMin(limit);
    update_couples();
  }
}

void SplineActuation::add_loads(const RodModel&, RodState& state) {
  state.external_torques += couples_;
}

void SplineActuation::save_state(SnapshotWriter& out) const {
  out.section("SplineActuation");
  out.put_matrix(targets_);
  out.put_matrix(current_);
}

void SplineActuation::load_state(SnapshotReader& in) {
  in.section("SplineActuation");
  Eigen::VectorXd targets = targets_, current = current_;
  in.get_matrix(targets);
  in.get_matrix(current);
  targets_ = std::move(targets);
  current_ = std::move(current);
  update_couples();
}

}  // namespace tendril::physics
