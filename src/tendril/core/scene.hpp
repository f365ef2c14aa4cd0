#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace tendril {

// What a viewer draws of an environment at one instant: a few kinds of primitives, lab frame,
// metres, each with a `role` that says what it is ("arm", "target", "obstacle", "goal", "path",
// ...; viewers colour by role). Environments fill it through Env::describe_scene; recorders,
// the dashboard and figures read only this, never an environment's internals.
struct Scene {
  struct Rod {  // a slender body drawn along its centreline
    std::string role;
    Eigen::Matrix3Xd centreline;  // nodes, base first
    Eigen::VectorXd radii;        // one per segment (centreline.cols() − 1), or one for all
  };
  struct Sphere {
    std::string role;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0.0;
  };
  struct Cylinder {  // from `start` to `end`; `capped` draws hemispherical ends (a capsule)
    std::string role;
    Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
    double radius = 0.0;
    bool capped = false;
  };
  struct Box {  // a rigid body's pose: centre and orientation (body → lab)
    std::string role;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  };
  struct Plane {
    std::string role;
    Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();
  };
  struct Lattice {  // mass-spring networks: nodes and the springs between them
    std::string role;
    Eigen::Matrix3Xd nodes;
    std::vector<std::array<int, 2>> springs;  // node index pairs
  };
  struct Path {  // a polyline: a reference trajectory, a target's path, waypoints
    std::string role;
    Eigen::Matrix3Xd points;
  };

  double time = 0.0;  // s since the episode began
  std::vector<Rod> rods;
  std::vector<Sphere> spheres;
  std::vector<Cylinder> cylinders;
  std::vector<Box> boxes;
  std::vector<Plane> planes;
  std::vector<Lattice> lattices;
  std::vector<Path> paths;
  std::vector<std::pair<std::string, double>> values;  // text shown beside the 3D view

  void clear() { *this = Scene(); }
};

}  // namespace tendril
