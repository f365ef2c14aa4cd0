#include "tendril/physics/lattice/row_couples.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics {

RowCouples::RowCouples(std::vector<Pair> pairs)
    : pairs_(std::move(pairs)), torques_(Eigen::VectorXd::Zero(pairs_.size())) {}

void RowCouples::attach(const LatticeModel& model) {
  for (const Pair& pair : pairs_) {
    const bool valid = pair[0] >= 0 && pair[0] < model.n_nodes() && pair[1] >= 0 &&
                       pair[1] < model.n_nodes() && pair[0] != pair[1];
    require(valid,
            "couple pair (" + std::to_string(pair[0]) + ", " + std::to_string(pair[1]) +
                ") is not two distinct nodes of " + std::to_string(model.n_nodes()),
            "RowCouples");
  }
}

void RowCouples::add_forces(const LatticeModel& /*model*/, const Eigen::Matrix2Xd& positions,
                            Eigen::Matrix2Xd& forces) const {
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const Eigen::Vector2d across = positions.col(pairs_[i][1]) - positions.col(pairs_[i][0]);
    // (τ / w) n = (τ / w²) ẑ × across
    const Eigen::Vector2d force =
        (torques_[i] / across.squaredNorm()) * Eigen::Vector2d(-across.y(), across.x());
    forces.col(pairs_[i][1]) += force;
    forces.col(pairs_[i][0]) -= force;
  }
}

void RowCouples::set_torques(const Eigen::VectorXd& torques) {
  require(torques.size() == torques_.size(),
          "expected " + std::to_string(torques_.size()) + " torques, got " +
              std::to_string(torques.size()),
          "RowCouples::set_torques");
  require(torques.allFinite(), "torques must be finite", "RowCouples::set_torques");
  torques_ = torques;
}

void RowCouples::save_state(SnapshotWriter& out) const {
  out.section("RowCouples");
  out.put_matrix(torques_);
}

void RowCouples::load_state(SnapshotReader& in) {
  in.section("RowCouples");
  Eigen::VectorXd torques = torques_;
  in.get_matrix(torques);
  torques_ = std::move(torques);
}

}  // namespace tendril::physics
