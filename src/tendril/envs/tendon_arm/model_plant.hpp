#pragma once

#include <memory>

#include "tendril/envs/learned/dynamics_model.hpp"
#include "tendril/envs/learned/history_windows.hpp"
#include "tendril/envs/tendon_arm/plant.hpp"

namespace tendril::envs::tendon_arm {

// The plant as a learned model of the arm, x_{t+1} = F(x_t … x_{t−n+1}, u_t … u_{t−n+1}) with x
// the tip (m) and u the tensions (N), run recursively on its own predictions: the model's window
// of [tip, tensions] rows is this plant's whole state. A reset fills every row with the rest tip
// and slack tendons (the arm hanging still), so a deterministic model starts every episode alike.
class ModelPlant final : public Plant {
 public:
  // Raises Error unless the model maps 3 tip coordinates and `tendons` ≥ 1 tensions to 3 tip
  // coordinates, `rest` is finite and max_tension positive.
  ModelPlant(std::shared_ptr<DynamicsModel> model, const Eigen::Vector3d& rest, double max_tension);

  int tendons() const override { return model_->input_dim(); }
  double max_tension() const override { return max_tension_; }
  Eigen::Vector3d reset(std::optional<uint64_t> seed) override;
  Eigen::Vector3d step(const Eigen::VectorXd& tensions) override;
  bool finite() const override { return finite_; }
  bool supports_snapshots() const override { return true; }
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;
  // The predicted tip as a sphere and the line from the base to it.
  void describe_scene(Scene& scene) const override;

  const DynamicsModel& model() const { return *model_; }

 private:
  std::shared_ptr<DynamicsModel> model_;
  Eigen::Vector3d rest_;
  double max_tension_;
  HistoryWindows windows_;
  BatchMatrix inputs_, next_;
  Eigen::Vector3d tip_;
  bool finite_ = true;
};

}  // namespace tendril::envs::tendon_arm
