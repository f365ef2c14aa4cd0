#pragma once

#include <cmath>
#include <cstdint>

#include "tendril/core/rng.hpp"
#include "tendril/dynamics/sequence_data.hpp"

namespace tendril::testing {

// Recorded trajectories of a known nonlinear system shaped like seed 001's limb, for tests and
// benchmarks: two bending angles θ (deg) driven by two throttles u ∈ [−10, 10] through a
// first-order "heat" lag h (τ_h = 0.8 s), with a stiffening spring and cross-coupling:
//   ḣ = (u − h) / τ_h
//   θ̈ = −k θ (1 + θ² / (2·60²)) − c θ̇ + b h + κ (θ_other − θ)
// k = 6 s⁻², c = 2.5 s⁻¹, b = 40 deg/s² per throttle, κ = 0.5 s⁻² (full throttle holds θ near
// 50°). Integrated with 10 semi-implicit Euler substeps per sample; samples every `period` seconds
// with ±10 % jitter; state [θx, θy, θ̇x, θ̇y]; throttles held for 10 samples, integers drawn
// uniformly. The last `test_fraction` of the rows form the test split.
struct SyntheticLimb {
  double period = 0.07;
  double test_fraction = 0.2;

  dynamics::SequenceData generate(int64_t rows, uint64_t seed) const {
    Rng rng(seed, 7);
    dynamics::SequenceData data;
    data.source = "synthetic limb";
    data.state_names = {"theta_x", "theta_y", "omega_x", "omega_y"};
    data.input_names = {"u_x", "u_y"};
    data.time.resize(rows);
    data.states.resize(rows, 4);
    data.inputs.resize(rows, 2);
    data.split.resize(static_cast<std::size_t>(rows));
    double theta[2] = {0, 0}, omega[2] = {0, 0}, heat[2] = {0, 0}, u[2] = {0, 0}, time = 0.0;
    const auto test_begin = static_cast<int64_t>(std::llround((1.0 - test_fraction) * rows));
    for (int64_t t = 0; t < rows; ++t) {
      if (t % 10 == 0) {
        for (double& throttle : u) throttle = static_cast<double>(rng.below(21)) - 10.0;
      }
      data.time(t) = time;
      data.states.row(t) << theta[0], theta[1], omega[0], omega[1];
      data.inputs.row(t) << u[0], u[1];
      data.split[static_cast<std::size_t>(t)] =
          t < test_begin ? dynamics::Split::kTrain : dynamics::Split::kTest;
      const double dt = period * rng.uniform(0.9, 1.1);
      const double h = dt / 10.0;
      for (int substep = 0; substep < 10; ++substep) {
        double accel[2];
        for (int a = 0; a < 2; ++a) {
          heat[a] += h * (u[a] - heat[a]) / 0.8;
          accel[a] = -6.0 * theta[a] * (1.0 + theta[a] * theta[a] / (2.0 * 3600.0)) -
                     2.5 * omega[a] + 40.0 * heat[a] + 0.5 * (theta[1 - a] - theta[a]);
        }
        for (int a = 0; a < 2; ++a) {
          omega[a] += h * accel[a];
          theta[a] += h * omega[a];
        }
      }
      time += dt;
    }
    return data;
  }
};

}  // namespace tendril::testing
