#pragma once

#include "tendril/nn/actor_critic.hpp"
#include "tendril/nn/inference_policy.hpp"

namespace tendril::nn {

// Copies every weight of `module` into `policy`, which must have been built from the same
// spec. Called after each update so rollouts act with the current parameters.
void sync_inference_policy(const ActorCriticImpl& module, InferencePolicy& policy);

// A new inference copy of `module`.
InferencePolicy make_inference_policy(const ActorCriticImpl& module);

}  // namespace tendril::nn
