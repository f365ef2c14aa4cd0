#pragma once

#include <Eigen/Core>

#include "tendril/physics/rod/rod_part.hpp"

namespace tendril::physics {

// Uniform gravity: F_j += m_j g on every node. g in m/s², lab frame.
class Gravity final : public RodPart {
 public:
  explicit Gravity(const Eigen::Vector3d& acceleration = Eigen::Vector3d(0.0, 0.0, -9.80665));
  uint32_t stages() const override { return kLoads; }
  void add_loads(const RodModel& model, RodState& state) override;

  const Eigen::Vector3d& acceleration() const { return acceleration_; }

 private:
  Eigen::Vector3d acceleration_;
};

// Forces on the two end nodes (lab frame, N), ramped linearly from zero over `ramp_time`
// seconds (0: applied at once) — the usual way to load a rod without exciting waves.
class EndForces final : public RodPart {
 public:
  EndForces(const Eigen::Vector3d& start_force, const Eigen::Vector3d& end_force,
            double ramp_time = 0.0);
  uint32_t stages() const override { return kLoads; }
  void add_loads(const RodModel& model, RodState& state) override;

  void set_end_force(const Eigen::Vector3d& force) { end_force_ = force; }
  const Eigen::Vector3d& start_force() const { return start_force_; }
  const Eigen::Vector3d& end_force() const { return end_force_; }
  double ramp_time() const { return ramp_time_; }

 private:
  Eigen::Vector3d start_force_, end_force_;
  double ramp_time_;
};

// Per-node external forces (lab frame, N), set by the owner between steps.
class NodeForces final : public RodPart {
 public:
  uint32_t stages() const override { return kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void add_loads(const RodModel& model, RodState& state) override;

  Vectors& forces() { return forces_; }  // 3 × (n + 1)

 private:
  Vectors forces_;
};

// Per-element external forces (lab frame, N), set by the owner between steps; each is shared
// half-and-half by the element's two nodes (e.g. drag or a load spread over an element).
class ElementForces final : public RodPart {
 public:
  uint32_t stages() const override { return kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void add_loads(const RodModel& model, RodState& state) override;

  Vectors& forces() { return forces_; }  // 3 × n

 private:
  Vectors forces_;
};

// Per-element external couples in the material frame (N·m; components along d1, d2, d3), set
// by the owner between steps. The soft arm's muscle actuation enters here (the Elastica RL
// paper: c_m = A_m, m = 1, 2, 3).
class ElementCouples final : public RodPart {
 public:
  uint32_t stages() const override { return kLoads; }
  void attach(const RodModel& model, const RodState& state) override;
  void add_loads(const RodModel& model, RodState& state) override;

  Vectors& couples() { return couples_; }  // 3 × n

 private:
  Vectors couples_;
};

}  // namespace tendril::physics
