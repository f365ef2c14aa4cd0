#pragma once

#include <functional>

#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/checkpoint.hpp"

namespace tendril::rl {

// The running statistics of the observation and reward normalizers wrapping the envs of a
// VecEnv, in and out of checkpoints (SB3 saves its VecNormalize beside the model).
void save_normalizers(envs::VecEnv& env, CheckpointWriter& writer);
// Reads them for the same VecEnv layout; the returned action installs them (run it once every
// read has succeeded, so a bad checkpoint changes nothing).
std::function<void()> prepare_normalizers(envs::VecEnv& env, CheckpointReader& reader);

}  // namespace tendril::rl
