#pragma once

#include <Eigen/Core>
#include <cmath>

#include "tendril/physics/rod/rod.hpp"

namespace tendril::envs::elastica {

// Allocation-free node read-outs for the per-step observation and intersection test.
// `Rod::sampled_node_positions` returns a freshly allocated matrix, which the hot path of an
// RL step avoids; these read single node columns instead and follow the same sampling rule,
// so `sampled_node(rod, k, count)` equals `rod.sampled_node_positions(count).col(k)` (checked
// by the observation-layout tests). Only `positions.col(node)` of the rod's state is used,
// which reads the same whatever the storage order of the positions.

// Node index of sample k of `count` evenly spread samples, both ends included:
// round(k·n / (count − 1)), as in Rod::sampled_node_positions.
inline int sampled_node_index(int k, int n_elements, int count) {
  return static_cast<int>(std::lround(static_cast<double>(k) * n_elements / (count - 1)));
}

// Position of node `node` (0 … n), lab frame, m.
inline Eigen::Vector3d node_position(const physics::Rod& rod, int node) {
  return rod.state().positions.col(node);
}

inline Eigen::Vector3d sampled_node(const physics::Rod& rod, int k, int count) {
  return node_position(rod, sampled_node_index(k, rod.n_elements(), count));
}

}  // namespace tendril::envs::elastica
