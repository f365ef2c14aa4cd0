#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "tendril/physics/lattice/lattice_load.hpp"

namespace tendril::physics {

// Pure couples on pairs of nodes (the outer nodes of a lattice row): couple i, of torque τ_i
// (N·m, counter-clockwise positive about +z), acts on its pair (left, right) as
//   F_right = +(τ_i / w) n,   F_left = −(τ_i / w) n,   w = |x_right − x_left|,
//   n = ẑ × (x_right − x_left)/w   (the in-plane normal of the row),
// so the net force is zero and the moment about any point is (x_right − x_left) × F_right =
// τ_i ẑ, whatever the row's current length and orientation (a follower couple). This is how
// seed 003's five torques act "between nodes 16–18, …, 88–90"; the middle node of a row gets
// no force.
class RowCouples final : public LatticeLoad {
 public:
  using Pair = std::array<int, 2>;  // {left, right} node indices

  explicit RowCouples(std::vector<Pair> pairs);

  void attach(const LatticeModel& model) override;
  void add_forces(const LatticeModel& model, const Eigen::Matrix2Xd& positions,
                  Eigen::Matrix2Xd& forces) const override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  // Raises tendril::Error unless `torques` has one finite value per pair.
  void set_torques(const Eigen::VectorXd& torques);
  const Eigen::VectorXd& torques() const { return torques_; }  // N·m
  const std::vector<Pair>& pairs() const { return pairs_; }

 private:
  std::vector<Pair> pairs_;
  Eigen::VectorXd torques_;
};

}  // namespace tendril::physics
