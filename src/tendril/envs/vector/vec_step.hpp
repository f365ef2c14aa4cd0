#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tendril/core/batch_matrix.hpp"
#include "tendril/core/env.hpp"

namespace tendril::envs {

using tendril::BatchMatrix;

// The result of stepping every environment of a VecEnv once. With a VecNormalize attached,
// observations, final observations and rewards are the normalized ones, while the infos'
// episode statistics stay raw.
struct VecStep {
  // Row i: env i's next observation. Where env i's episode ended on this step, the environment
  // has already been reset and this is the first observation of its next episode.
  BatchMatrix observations;
  // Row i: the observation that followed this step within env i's own episode — equal to
  // `observations` row i unless the episode ended, in which case it is the episode's final
  // observation (bootstrap from it through a truncation).
  BatchMatrix final_observations;
  Eigen::VectorXf rewards;
  std::vector<uint8_t> terminated;  // 1 where the task ended (do not bootstrap)
  std::vector<uint8_t> truncated;   // 1 where a time limit cut the episode (bootstrap)
  std::vector<Info> infos;          // env i's info for this step (episode statistics included)

  bool done(int i) const { return terminated[i] != 0 || truncated[i] != 0; }
};

}  // namespace tendril::envs
