#pragma once

#include <Eigen/Core>

#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// A push on the tip: a force (lab frame, N) on the last node until a given time — a hand or a
// tool disturbing the limb. Set by the owner between steps; kept in snapshots.
class TipPush final : public RodPart {
 public:
  uint32_t stages() const override { return kLoads; }
  void add_loads(const RodModel& model, RodState& state) override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  // Pushes with `force` from now until `until` (s, rod time). Raises Error on non-finite input.
  void push(const Eigen::Vector3d& force, double until);
  const Eigen::Vector3d& force() const { return force_; }
  double until() const { return until_; }

 private:
  Eigen::Vector3d force_ = Eigen::Vector3d::Zero();
  double until_ = 0.0;
};

}  // namespace tendril::physics
