#include "tendril/physics/rigid/ur5_mjcf.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

struct Capsule {
  const char* name;
  Eigen::Vector3d from, to;  // m, body frame
  double radius;             // m
};

// A link's inertia as a solid cylinder of radius r and length L along one body axis (0 x, 2 z).
struct CylinderInertia {
  double radius, length;
  int axis;
};

// Each link's geometry in its body frame (ur5_mjcf.hpp): the DH offsets of the link with the
// real lateral offsets of the shoulder, upper arm and forearm.
std::vector<Capsule> link_capsules(int link) {
  using namespace ur5;
  const double d1 = kDhD[0];
  switch (link) {
    case 0:
      return {{"base_column", {0, 0, 0}, {0, 0, d1}, 0.06},
              // Joint 2's axis is −y in this frame; the upper arm sits kUpperArmOffset along it.
              {"shoulder", {0, 0, d1}, {0, -kUpperArmOffset, d1}, 0.06}};
    case 1:
      return {{"upper_arm", {0, 0, kUpperArmOffset}, {kDhA[1], 0, kUpperArmOffset}, 0.05},
              {"elbow", {kDhA[1], 0, kUpperArmOffset}, {kDhA[1], 0, kForearmOffset}, 0.045}};
    case 2:
      return {{"forearm", {0, 0, kForearmOffset}, {kDhA[2], 0, kForearmOffset}, 0.04}};
    case 3:
      return {{"wrist_1", {0, 0, kForearmOffset}, {0, 0, kDhD[3]}, 0.04}};
    case 4:
      return {{"wrist_2", {0, 0, 0}, {0, 0, kDhD[4]}, 0.04}};
    default:
      // The end cap's far pole is the flange.
      return {{"wrist_3", {0, 0, 0}, {0, 0, kDhD[5] - 0.035}, 0.035}};
  }
}

CylinderInertia link_cylinder(int link) {
  constexpr std::array<CylinderInertia, ur5::kJoints> kCylinders = {{
      {0.06, 0.15, 2},
      {0.05, 0.425, 0},
      {0.04, 0.39225, 0},
      {0.04, 0.12, 2},
      {0.04, 0.12, 2},
      {0.035, 0.05, 2},
  }};
  return kCylinders[link];
}

std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream text;
  text.precision(17);
  text << v.x() << ' ' << v.y() << ' ' << v.z();
  return text.str();
}

// MuJoCo quaternions are (w, x, y, z).
std::string rotation_about_x(double angle) {
  std::ostringstream text;
  text.precision(17);
  text << std::cos(angle / 2) << ' ' << std::sin(angle / 2) << " 0 0";
  return text.str();
}

void write_link(std::ostringstream& xml, int link, const Ur5SceneSpec& spec) {
  using namespace ur5;
  // DH frame `link` (where the published centre of mass is given) in this body's frame.
  const Eigen::Vector3d distal_origin(kDhA[link], 0.0, kDhD[link]);
  const Eigen::Matrix3d distal_rotation =
      Eigen::AngleAxisd(kDhAlpha[link], Eigen::Vector3d::UnitX()).toRotationMatrix();
  const auto& com = kLinkCentreOfMass[link];
  const Eigen::Vector3d centre =
      distal_origin + distal_rotation * Eigen::Vector3d(com[0], com[1], com[2]);
  const CylinderInertia cylinder = link_cylinder(link);
  const double m = kLinkMass[link];
  const double axial = 0.5 * m * cylinder.radius * cylinder.radius;
  const double transverse =
      m * (3 * cylinder.radius * cylinder.radius + cylinder.length * cylinder.length) / 12.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Constant(transverse);
  inertia[cylinder.axis] = axial;

  xml << "<inertial pos='" << vec(centre) << "' mass='" << m << "' diaginertia='" << vec(inertia)
      << "'/>\n";
  xml << "<joint name='" << kJointNames[link]
      << "' type='hinge' axis='0 0 1' limited='true' range='" << -kJointUpper[link] << ' '
      << kJointUpper[link] << "' damping='" << spec.damping[link] << "' armature='"
      << spec.armature[link] << "'/>\n";
  for (const Capsule& capsule : link_capsules(link)) {
    xml << "<geom name='" << capsule.name << "' type='capsule' fromto='" << vec(capsule.from) << ' '
        << vec(capsule.to) << "' size='" << capsule.radius << "'/>\n";
  }
}

}  // namespace

void Ur5SceneSpec::validate() const {
  const std::string where = "Ur5SceneSpec";
  require(std::isfinite(timestep) && timestep > 0.0, "timestep must be finite and positive", where);
  for (int i = 0; i < ur5::kJoints; ++i) {
    require(std::isfinite(stiffness[i]) && stiffness[i] > 0.0,
            "stiffness must be finite and positive", where);
    require(std::isfinite(damping[i]) && damping[i] >= 0.0, "damping must be finite and >= 0",
            where);
    require(std::isfinite(armature[i]) && armature[i] >= 0.0, "armature must be finite and >= 0",
            where);
  }
  require(obstacle_centre.allFinite(), "obstacle_centre must be finite", where);
  require(obstacle_half_extents.allFinite() && (obstacle_half_extents.array() > 0.0).all(),
          "obstacle_half_extents must be finite and positive", where);
}

std::string ur5_mjcf(const Ur5SceneSpec& spec) {
  using namespace ur5;
  spec.validate();
  std::ostringstream xml;
  xml.precision(17);
  xml << "<mujoco model='ur5_reach'>\n"
      << "<compiler angle='radian' inertiafromgeom='false'/>\n"
      << "<option timestep='" << spec.timestep << "' integrator='Euler' gravity='0 0 -9.81'/>\n"
      << "<worldbody>\n"
      << "<geom name='" << ur5_names::kTableGeom << "' type='plane' size='1.5 1.5 0.01'/>\n"
      << "<geom name='" << ur5_names::kObstacleGeom << "' type='box' pos='"
      << vec(spec.obstacle_centre) << "' size='" << vec(spec.obstacle_half_extents) << "'/>\n";
  // Body k+1 is nested in body k at DH link k's offset and twist.
  for (int link = 0; link < kJoints; ++link) {
    xml << "<body name='" << ur5_names::kLinkBodies[link] << "'";
    if (link > 0) {
      xml << " pos='" << vec(Eigen::Vector3d(kDhA[link - 1], 0.0, kDhD[link - 1])) << "' quat='"
          << rotation_about_x(kDhAlpha[link - 1]) << "'";
    }
    xml << ">\n";
    write_link(xml, link, spec);
  }
  xml << "<site name='" << ur5_names::kFlangeSite << "' pos='"
      << vec(Eigen::Vector3d(kDhA[5], 0.0, kDhD[5])) << "' quat='" << rotation_about_x(kDhAlpha[5])
      << "' size='0.01'/>\n";
  for (int link = 0; link < kJoints; ++link) xml << "</body>\n";
  xml << "</worldbody>\n"
      << "<contact><exclude body1='world' body2='" << ur5_names::kLinkBodies[0] << "'/></contact>\n"
      << "<actuator>\n";
  for (int joint = 0; joint < kJoints; ++joint) {
    xml << "<position name='" << kJointNames[joint] << "' joint='" << kJointNames[joint] << "' kp='"
        << spec.stiffness[joint] << "' ctrllimited='true' ctrlrange='" << -kJointUpper[joint] << ' '
        << kJointUpper[joint] << "' forcelimited='true' forcerange='" << -kMaxTorque[joint] << ' '
        << kMaxTorque[joint] << "'/>\n";
  }
  xml << "</actuator>\n</mujoco>\n";
  return xml.str();
}

}  // namespace tendril::physics
