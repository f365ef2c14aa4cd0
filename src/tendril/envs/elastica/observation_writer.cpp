#include "tendril/envs/elastica/observation_writer.hpp"

#include "tendril/envs/elastica/rod_readout.hpp"

namespace tendril::envs::elastica {

void ObservationWriter::rod_nodes(const physics::Rod& rod) {
  const int n = rod.n_elements();
  for (int coordinate = 0; coordinate < 3; ++coordinate) {
    for (int k = 0; k < kRodSamples; ++k) {
      put(node_position(rod, sampled_node_index(k, n, kRodSamples))[coordinate]);
    }
  }
}

void ObservationWriter::speed_and_direction(const Eigen::Vector3d& velocity) {
  const double speed = velocity.norm();
  put(speed);
  const Eigen::Vector3d direction =
      speed > 0.0 ? Eigen::Vector3d(velocity / speed) : Eigen::Vector3d::Zero();
  position(direction);
}

void ObservationWriter::position(const Eigen::Vector3d& position) {
  for (int coordinate = 0; coordinate < 3; ++coordinate) put(position[coordinate]);
}

void ObservationWriter::quaternion(const Eigen::Quaterniond& q) {
  put(q.w());
  put(q.x());
  put(q.y());
  put(q.z());
}

void ObservationWriter::obstacle(const physics::Cylinder& cylinder) {
  for (int coordinate = 0; coordinate < 3; ++coordinate) {
    for (int i = 0; i < kObstaclePoints; ++i) {
      const double along = cylinder.length * i / (kObstaclePoints - 1);
      put(cylinder.start[coordinate] + along * cylinder.axis[coordinate]);
    }
  }
}

}  // namespace tendril::envs::elastica
