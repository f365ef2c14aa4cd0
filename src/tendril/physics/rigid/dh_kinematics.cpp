#include "tendril/physics/rigid/dh_kinematics.hpp"

#include <string>

#include "tendril/core/error.hpp"
#include "tendril/physics/rigid/ur5_parameters.hpp"

namespace tendril::physics {

Eigen::Isometry3d dh_transform(const DhLink& link, double theta) {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.rotate(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()));
  transform.translate(Eigen::Vector3d(link.a, 0.0, link.d));
  transform.rotate(Eigen::AngleAxisd(link.alpha, Eigen::Vector3d::UnitX()));
  return transform;
}

std::vector<Eigen::Isometry3d> dh_frames(std::span<const DhLink> links, const Eigen::VectorXd& q) {
  require(
      static_cast<std::size_t>(q.size()) == links.size(),
      "expected " + std::to_string(links.size()) + " joint angles, got " + std::to_string(q.size()),
      "dh_frames");
  std::vector<Eigen::Isometry3d> frames;
  frames.reserve(links.size());
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < links.size(); ++i) {
    pose = pose * dh_transform(links[i], q[static_cast<Eigen::Index>(i)]);
    frames.push_back(pose);
  }
  return frames;
}

Eigen::Isometry3d dh_forward_kinematics(std::span<const DhLink> links, const Eigen::VectorXd& q) {
  return dh_frames(links, q).back();
}

std::vector<DhLink> ur5_dh_links() {
  std::vector<DhLink> links(ur5::kJoints);
  for (int i = 0; i < ur5::kJoints; ++i) {
    links[i] = {ur5::kDhA[i], ur5::kDhD[i], ur5::kDhAlpha[i]};
  }
  return links;
}

}  // namespace tendril::physics
