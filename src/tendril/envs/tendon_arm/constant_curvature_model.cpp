#include "tendril/envs/tendon_arm/constant_curvature_model.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs::tendon_arm {

ConstantCurvatureModel::ConstantCurvatureModel(const ArmSpec& spec, const Eigen::Vector3d& rest)
    : spec_(spec), rest_(rest), beta_(1.0 - std::exp(-spec.control_period / kLag)) {
  spec_.validate();
  require(rest_.allFinite(), "the rest tip must be finite", "tendon_arm::ConstantCurvatureModel");
}

Eigen::Vector3d ConstantCurvatureModel::steady_tip(const Eigen::VectorXd& tensions) const {
  // Tendon k sits at material angle φ_k from d1 = x about d3 = −z, i.e. towards (cos φ_k,
  // −sin φ_k, 0) in the lab, and bends the arm towards itself.
  Eigen::Vector2d couple = Eigen::Vector2d::Zero();
  for (int k = 0; k < spec_.tendons; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / spec_.tendons;
    couple += std::max(0.0, tensions[k]) * spec_.tendon_offset *
              Eigen::Vector2d(std::cos(angle), -std::sin(angle));
  }
  const double theta = couple.norm() / spec_.bending_stiffness() * spec_.length;
  if (theta < 1e-9) return rest_;
  const Eigen::Vector2d direction = couple.normalized();
  const double sideways = spec_.length * (1.0 - std::cos(theta)) / theta;
  const double rise = spec_.length * (1.0 - std::sin(theta) / theta);
  return rest_ + Eigen::Vector3d(sideways * direction.x(), sideways * direction.y(), rise);
}

void ConstantCurvatureModel::predict(const BatchMatrix& windows, BatchMatrix& next_states) {
  const int row = 3 + spec_.tendons;
  require(windows.cols() == row, "windows of the wrong width",
          "tendon_arm::ConstantCurvatureModel");
  next_states.resize(windows.rows(), 3);
  for (Eigen::Index env = 0; env < windows.rows(); ++env) {
    const Eigen::Vector3d tip = windows.row(env).head<3>().transpose().cast<double>();
    const Eigen::VectorXd tensions =
        windows.row(env).segment(3, spec_.tendons).transpose().cast<double>();
    next_states.row(env) = (tip + beta_ * (steady_tip(tensions) - tip)).transpose().cast<float>();
  }
}

}  // namespace tendril::envs::tendon_arm
