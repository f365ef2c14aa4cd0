#include "tendril/envs/tendon_arm/model_plant.hpp"

#include <cmath>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs::tendon_arm {

namespace {

constexpr const char* kWhere = "tendon_arm::ModelPlant";

const DynamicsModel& checked(const std::shared_ptr<DynamicsModel>& model) {
  require(model != nullptr, "no model", kWhere);
  require(model->state_dim() == 3 && model->input_dim() >= 1,
          "the model must map the tip (3 coordinates) and the tendon tensions to the tip, not " +
              std::to_string(model->state_dim()) + " states and " +
              std::to_string(model->input_dim()) + " inputs",
          kWhere);
  return *model;
}

}  // namespace

ModelPlant::ModelPlant(std::shared_ptr<DynamicsModel> model, const Eigen::Vector3d& rest,
                       double max_tension)
    : model_(std::move(model)),
      rest_(rest),
      max_tension_(max_tension),
      windows_(1, checked(model_).window_length(), 3, model_->input_dim()),
      inputs_(BatchMatrix::Zero(1, model_->input_dim())),
      tip_(rest) {
  require(rest_.allFinite(), "the rest tip must be finite", kWhere);
  require(std::isfinite(max_tension_) && max_tension_ > 0.0, "max_tension must be positive",
          kWhere);
  windows_.reset(0, rest_.cast<float>());
}

Eigen::Vector3d ModelPlant::reset(std::optional<uint64_t> /*seed*/) {
  tip_ = rest_;
  windows_.reset(0, tip_.cast<float>());
  finite_ = true;
  return tip_;
}

Eigen::Vector3d ModelPlant::step(const Eigen::VectorXd& tensions) {
  require(tensions.size() == inputs_.cols(), "wrong number of tensions", kWhere);
  inputs_.row(0) = tensions.transpose().cast<float>();
  model_->step(windows_, inputs_, next_);
  tip_ = next_.row(0).transpose().cast<double>();
  finite_ = tip_.allFinite();
  return tip_;
}

void ModelPlant::save_state(SnapshotWriter& out) const {
  out.section(kWhere);
  windows_.save_state(out);
  out.put_matrix(tip_);
  out.put(finite_);
}

void ModelPlant::load_state(SnapshotReader& in) {
  in.section(kWhere);
  HistoryWindows windows = windows_;
  windows.load_state(in);
  Eigen::Vector3d tip;
  in.get_matrix(tip);
  const bool finite = in.get_bool();
  windows_ = std::move(windows);
  tip_ = tip;
  finite_ = finite;
}

void ModelPlant::describe_scene(Scene& scene) const {
  Scene::Path arm;
  arm.role = "arm";
  arm.points = Eigen::Matrix3Xd::Zero(3, 2);
  arm.points.col(1) = tip_;
  scene.paths.push_back(std::move(arm));
  scene.spheres.push_back({"tip", tip_, 0.006});
}

}  // namespace tendril::envs::tendon_arm
