#pragma once

#include <Eigen/Core>

namespace tendril::physics::pneumatic {

// The pneumatic arm of seed 002 (Nazeer et al., §III-A): three modules, each bent and extended
// by three chambers at 120°, nine pressure signals. Chamber c of module m (both from 0; module
// 0 is attached to the base) has the flat index 3 m + c everywhere: commands, pressures, data
// files ("module 1 chamber 1" in the paper's counting is index 0).
inline constexpr int kModules = 3;
inline constexpr int kChambersPerModule = 3;
inline constexpr int kChambers = kModules * kChambersPerModule;

// One value per chamber (bar unless stated), in flat index order.
using ChamberVector = Eigen::Matrix<double, kChambers, 1>;
// The three module-tip positions as columns, module 0 first.
using TipPositions = Eigen::Matrix3d;

inline constexpr int chamber_index(int module, int chamber) {
  return kChambersPerModule * module + chamber;
}

}  // namespace tendril::physics::pneumatic
