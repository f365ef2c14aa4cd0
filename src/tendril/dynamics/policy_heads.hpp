#pragma once

namespace tendril::dynamics {

// Makes "lk_encoder" and "lk_full" heads (LearnedModelHead) known to algorithms and policy files
// (nn::install_feature_head_kind): made from `head.model` (a model file or fit run) with its
// weights when `head.pretrained`, else with a fresh initialisation (the model library's default)
// from the algorithm's stream. Programs that link this layer call it once at start-up, as they
// install the model loader of learned-model envs.
void install_policy_heads();

}  // namespace tendril::dynamics
