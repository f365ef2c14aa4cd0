#include "tendril/physics/twins/sma/tip_push.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::physics {

void TipPush::add_loads(const RodModel& model, RodState& state) {
  if (state.time < until_) state.external_forces.col(model.n_elements) += force_;
}

void TipPush::push(const Eigen::Vector3d& force, double until) {
  require(force.allFinite() && std::isfinite(until), "push force and end time must be finite",
          "TipPush");
  force_ = force;
  until_ = until;
}

void TipPush::save_state(SnapshotWriter& out) const {
  out.section("TipPush");
  out.put_matrix(force_);
  out.put(until_);
}

void TipPush::load_state(SnapshotReader& in) {
  in.section("TipPush");
  Eigen::Vector3d force = force_;
  in.get_matrix(force);
  const double until = in.get_double();
  force_ = force;
  until_ = until;
}

}  // namespace tendril::physics
