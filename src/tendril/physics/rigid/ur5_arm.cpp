#include "tendril/physics/rigid/ur5_arm.hpp"

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

MujocoSim load(const Ur5SceneSpec& spec, const std::filesystem::path& model_file) {
  spec.validate();
  if (!model_file.empty()) return MujocoSim::from_file(model_file);
  return MujocoSim::from_xml(ur5_mjcf(spec), "UR5 scene");
}

Eigen::Matrix3d rotation(const mjtNum* xmat) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(xmat);
}

int unstable_warnings(const mjData* d) {
  return d->warning[mjWARN_BADQPOS].number + d->warning[mjWARN_BADQVEL].number +
         d->warning[mjWARN_BADQACC].number;
}

}  // namespace

Ur5Arm::Ur5Arm(const Ur5SceneSpec& spec, const std::filesystem::path& model_file)
    : sim_(load(spec, model_file)) {
  const mjModel* m = sim_.model();
  is_link_body_.assign(m->nbody, 0);
  for (int i = 0; i < ur5::kJoints; ++i) {
    const int joint = sim_.id_of(mjOBJ_JOINT, ur5::kJointNames[i]);
    require(m->jnt_type[joint] == mjJNT_HINGE,
            std::string("joint '") + ur5::kJointNames[i] + "' must be a hinge", sim_.name());
    qpos_address_[i] = m->jnt_qposadr[joint];
    dof_address_[i] = m->jnt_dofadr[joint];
    actuator_[i] = sim_.id_of(mjOBJ_ACTUATOR, ur5::kJointNames[i]);
    is_link_body_[sim_.id_of(mjOBJ_BODY, ur5_names::kLinkBodies[i])] = 1;
  }
  flange_site_ = sim_.id_of(mjOBJ_SITE, ur5_names::kFlangeSite);
  obstacle_geom_ = sim_.id_of(mjOBJ_GEOM, ur5_names::kObstacleGeom);
  require(m->geom_type[obstacle_geom_] == mjGEOM_BOX, "geom 'obstacle' must be a box", sim_.name());
  place(Joints::Zero());
}

Ur5Arm::Joints Ur5Arm::upper_limits() {
  Joints upper;
  for (int i = 0; i < ur5::kJoints; ++i) upper[i] = ur5::kJointUpper[i];
  return upper;
}

Ur5Arm::Joints Ur5Arm::lower_limits() { return -upper_limits(); }

void Ur5Arm::place(const Joints& q) {
  require(q.allFinite() && (q.array() >= lower_limits().array()).all() &&
              (q.array() <= upper_limits().array()).all(),
          "joint angles must be finite and within the joint limits", sim_.name());
  sim_.reset();
  const mjModel* m = sim_.model();
  mjData* d = sim_.data();
  for (int i = 0; i < ur5::kJoints; ++i) d->qpos[qpos_address_[i]] = q[i];
  set_targets(q);
  mj_forward(m, d);
}

const Ur5Arm::Joints& Ur5Arm::set_targets(const Joints& targets) {
  targets_ = targets.cwiseMax(lower_limits()).cwiseMin(upper_limits());
  for (int i = 0; i < ur5::kJoints; ++i) sim_.data()->ctrl[actuator_[i]] = targets_[i];
  return targets_;
}

Ur5Arm::Advance Ur5Arm::advance(int steps) {
  const mjModel* m = sim_.model();
  mjData* d = sim_.data();
  Advance report;
  const int warnings_before = unstable_warnings(d);
  for (int step = 0; step < steps; ++step) {
    // mj_step split around the bias compensation: step1 computes positions, contacts and
    // qfrc_bias; step2 applies forces and integrates (semi-implicit Euler).
    mj_step1(m, d);
    report.contacts = std::max(report.contacts, count_contacts());
    for (int dof = 0; dof < m->nv; ++dof) d->qfrc_applied[dof] = d->qfrc_bias[dof];
    mj_step2(m, d);
    if (unstable_warnings(d) != warnings_before) {
      report.stable = false;
      break;
    }
  }
  // Positions and contacts of the state reached.
  mj_kinematics(m, d);
  mj_collision(m, d);
  report.contacts = std::max(report.contacts, count_contacts());
  return report;
}

int Ur5Arm::count_contacts() const {
  const mjModel* m = sim_.model();
  const mjData* d = sim_.data();
  int count = 0;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& contact = d->contact[i];
    if (is_link_body_[m->geom_bodyid[contact.geom1]] ||
        is_link_body_[m->geom_bodyid[contact.geom2]]) {
      ++count;
    }
  }
  return count;
}

int Ur5Arm::contacts() const { return count_contacts(); }

Ur5Arm::Joints Ur5Arm::joint_positions() const {
  Joints q;
  for (int i = 0; i < ur5::kJoints; ++i) q[i] = sim_.data()->qpos[qpos_address_[i]];
  return q;
}

Ur5Arm::Joints Ur5Arm::joint_velocities() const {
  Joints v;
  for (int i = 0; i < ur5::kJoints; ++i) v[i] = sim_.data()->qvel[dof_address_[i]];
  return v;
}

Eigen::Vector3d Ur5Arm::flange_position() const {
  return Eigen::Map<const Eigen::Vector3d>(sim_.data()->site_xpos + 3 * flange_site_);
}

Eigen::Matrix3d Ur5Arm::flange_rotation() const {
  return rotation(sim_.data()->site_xmat + 9 * flange_site_);
}

double Ur5Arm::time() const { return sim_.data()->time; }
double Ur5Arm::timestep() const { return sim_.model()->opt.timestep; }

Eigen::Vector3d Ur5Arm::obstacle_centre() const {
  return Eigen::Map<const Eigen::Vector3d>(sim_.data()->geom_xpos + 3 * obstacle_geom_);
}

Eigen::Vector3d Ur5Arm::obstacle_half_extents() const {
  return Eigen::Map<const Eigen::Vector3d>(sim_.model()->geom_size + 3 * obstacle_geom_);
}

void Ur5Arm::describe(Scene& scene) const {
  const mjModel* m = sim_.model();
  const mjData* d = sim_.data();
  scene.time = d->time;
  for (int g = 0; g < m->ngeom; ++g) {
    const Eigen::Vector3d centre = Eigen::Map<const Eigen::Vector3d>(d->geom_xpos + 3 * g);
    const Eigen::Matrix3d orientation = rotation(d->geom_xmat + 9 * g);
    const Eigen::Vector3d size = Eigen::Map<const Eigen::Vector3d>(m->geom_size + 3 * g);
    const bool link = is_link_body_[m->geom_bodyid[g]] != 0;
    switch (m->geom_type[g]) {
      case mjGEOM_CAPSULE:
      case mjGEOM_CYLINDER: {
        const Eigen::Vector3d half = size[1] * orientation.col(2);
        scene.cylinders.push_back({link ? "arm" : "obstacle", centre - half, centre + half, size[0],
                                   m->geom_type[g] == mjGEOM_CAPSULE});
        break;
      }
      case mjGEOM_BOX:
        scene.boxes.push_back(
            {link ? "arm" : "obstacle", centre, size, Eigen::Quaterniond(orientation)});
        break;
      case mjGEOM_PLANE:
        scene.planes.push_back({"table", centre, orientation.col(2)});
        break;
      case mjGEOM_SPHERE:
        scene.spheres.push_back({link ? "arm" : "obstacle", centre, size[0]});
        break;
      default:
        break;  // meshes and height fields of a user's model are not drawn
    }
  }
}

void Ur5Arm::save_state(SnapshotWriter& out) const { sim_.save_state(out); }

void Ur5Arm::load_state(SnapshotReader& in) {
  sim_.load_state(in);
  read_targets();
  mj_collision(sim_.model(), sim_.data());
}

void Ur5Arm::read_targets() {
  for (int i = 0; i < ur5::kJoints; ++i) targets_[i] = sim_.data()->ctrl[actuator_[i]];
}

}  // namespace tendril::physics
