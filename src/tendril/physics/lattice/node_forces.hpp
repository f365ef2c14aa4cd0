#pragma once

#include <Eigen/Core>

#include "tendril/physics/lattice/lattice_load.hpp"

namespace tendril::physics {

// Fixed-direction forces on nodes (N, lab frame; a dead load such as a tip weight), set by the
// owner between steps.
class NodeForces final : public LatticeLoad {
 public:
  void attach(const LatticeModel& model) override {
    forces_ = Eigen::Matrix2Xd::Zero(2, model.n_nodes());
  }
  void add_forces(const LatticeModel& /*model*/, const Eigen::Matrix2Xd& /*positions*/,
                  Eigen::Matrix2Xd& forces) const override {
    forces += forces_;
  }
  void save_state(SnapshotWriter& out) const override {
    out.section("NodeForces");
    out.put_matrix(forces_);
  }
  void load_state(SnapshotReader& in) override {
    in.section("NodeForces");
    Eigen::Matrix2Xd forces = forces_;
    in.get_matrix(forces);
    forces_ = std::move(forces);
  }

  Eigen::Matrix2Xd& forces() { return forces_; }  // 2 × nodes

 private:
  Eigen::Matrix2Xd forces_;
};

}  // namespace tendril::physics
