#include "tendril/envs/vector/vec_env.hpp"

#include "tendril/core/error.hpp"

namespace tendril::envs {

void VecEnv::seed_next_reset(int /*env*/, uint64_t /*seed*/) {
  throw Error("this vector environment cannot seed single resets", "envs::VecEnv");
}

VecEnvWrapper::VecEnvWrapper(std::unique_ptr<VecEnv> inner) : inner_(std::move(inner)) {
  require(inner_ != nullptr, "cannot wrap a null vector environment", "envs::VecEnvWrapper");
}

}  // namespace tendril::envs
