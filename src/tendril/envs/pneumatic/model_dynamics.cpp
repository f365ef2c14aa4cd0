#include "tendril/envs/pneumatic/model_dynamics.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::pneumatic {

namespace {

constexpr const char* kWhere = "pneumatic::ModelDynamics";
constexpr uint64_t kJitterStream = 11;

const DynamicsModel& checked(const std::shared_ptr<DynamicsModel>& model) {
  require(model != nullptr, "no model", kWhere);
  require(model->state_dim() == 9 && model->input_dim() == 9,
          "the model must map 9 tip coordinates and 9 pressures to 9 tip coordinates, not " +
              std::to_string(model->state_dim()) + " and " + std::to_string(model->input_dim()),
          kWhere);
  return *model;
}

// A point drawn uniformly from the ball of `radius` around the origin (rejection from the
// enclosing cube: accepts π/6 ≈ 52 % of the draws).
Eigen::Vector3d uniform_in_ball(Rng& rng, double radius) {
  while (true) {
    const Eigen::Vector3d u(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
    if (u.squaredNorm() <= 1.0) return radius * u;
  }
}

}  // namespace

ModelDynamics::ModelDynamics(std::shared_ptr<DynamicsModel> model, const TipVector& rest_mm,
                             double rest_jitter_mm, double initial_offset_mm)
    : model_(std::move(model)),
      rest_(rest_mm),
      windows_(1, checked(model_).window_length(), 9, 9),
      inputs_(BatchMatrix::Zero(1, 9)),
      tips_(rest_mm),
      rest_jitter_mm_(rest_jitter_mm),
      initial_offset_mm_(initial_offset_mm),
      jitter_rng_(0, kJitterStream) {
  require(rest_.allFinite(), "the rest tips must be finite", kWhere);
  require(std::isfinite(rest_jitter_mm) && rest_jitter_mm >= 0.0,
          "the rest jitter must be finite and non-negative", kWhere);
  require(std::isfinite(initial_offset_mm) && initial_offset_mm >= 0.0,
          "the initial offset must be finite and non-negative, not " +
              std::to_string(initial_offset_mm),
          kWhere);
  windows_.reset(0, rest_.cast<float>());
}

TipVector ModelDynamics::reset(std::optional<uint64_t> seed) {
  tips_ = rest_;
  // Without jitter or offset no draw is made: the default episode is the one it always was.
  if (seed && (rest_jitter_mm_ > 0.0 || initial_offset_mm_ > 0.0)) {
    jitter_rng_ = Rng(*seed, kJitterStream);
  }
  if (rest_jitter_mm_ > 0.0) {
    for (int i = 0; i < 9; ++i) tips_[i] += rest_jitter_mm_ * jitter_rng_.normal();
  }
  if (initial_offset_mm_ > 0.0) {
    for (int module = 0; module < 3; ++module) {
      tips_.segment<3>(3 * module) += uniform_in_ball(jitter_rng_, initial_offset_mm_);
    }
  }
  windows_.reset(0, tips_.cast<float>());
  finite_ = true;
  return tips_;
}

TipVector ModelDynamics::step(const ChamberVector& pressures_bar) {
  inputs_.row(0) = pressures_bar.transpose().cast<float>();
  model_->step(windows_, inputs_, next_);
  tips_ = next_.row(0).transpose().cast<double>();
  finite_ = tips_.allFinite();
  return tips_;
}

void ModelDynamics::reset_to(const TipVector& measured_mm) {
  require(measured_mm.allFinite(), "measured tips must be finite", kWhere);
  windows_.reset(0, measured_mm.cast<float>());
  tips_ = measured_mm;
  finite_ = true;
}

TipVector ModelDynamics::predict_next(const ChamberVector& pressures_bar) {
  inputs_.row(0) = pressures_bar.transpose().cast<float>();
  windows_.set_inputs(inputs_);
  model_->predict(windows_.windows(), next_);
  return next_.row(0).transpose().cast<double>();
}

void ModelDynamics::follow(const TipVector& measured_mm) {
  require(measured_mm.allFinite(), "measured tips must be finite", kWhere);
  next_.row(0) = measured_mm.transpose().cast<float>();
  windows_.advance(next_);
  tips_ = measured_mm;
}

void ModelDynamics::save_state(SnapshotWriter& out) const {
  out.section("ModelDynamics");
  windows_.save_state(out);
  out.put_matrix(tips_);
  out.put(finite_);
  out.put(jitter_rng_);
}

void ModelDynamics::load_state(SnapshotReader& in) {
  in.section("ModelDynamics");
  HistoryWindows windows = windows_;
  windows.load_state(in);
  TipVector tips;
  in.get_matrix(tips);
  const bool finite = in.get_bool();
  Rng jitter_rng = jitter_rng_;
  in.get(jitter_rng);
  windows_ = std::move(windows);
  jitter_rng_ = jitter_rng;
  tips_ = tips;
  finite_ = finite;
}

void ModelDynamics::describe_scene(Scene& scene) const {
  constexpr double kMetresPerMillimetre = 1e-3;
  Scene::Path arm;
  arm.role = "arm";
  arm.points = Eigen::Matrix3Xd::Zero(3, 4);
  for (int module = 0; module < 3; ++module) {
    const Eigen::Vector3d tip = kMetresPerMillimetre * tips_.segment<3>(3 * module);
    arm.points.col(module + 1) = tip;
    scene.spheres.push_back({"module_tip", tip, 0.01});
  }
  scene.paths.push_back(std::move(arm));
}

}  // namespace tendril::envs::pneumatic
