#pragma once

#include <functional>

#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/checkpoint.hpp"

namespace tendril::rl {

// The state of a VecEnv's shared VecNormalize in and out of checkpoints (SB3 saves its
// VecNormalize beside the model): the observation statistics when observations are normalized;
// the return statistics and every env's running discounted return when rewards are.
void save_normalizers(const envs::VecEnv& env, CheckpointWriter& writer);
// Reads that state for `env`. Raises Error naming the checkpoint if it holds statistics `env`
// does not normalize with, lacks some that `env` needs, or was written for another observation
// size or number of envs. The returned action installs the state (run it once every read has
// succeeded, so a bad checkpoint changes nothing).
std::function<void()> prepare_normalizers(envs::VecEnv& env, CheckpointReader& reader);

}  // namespace tendril::rl
