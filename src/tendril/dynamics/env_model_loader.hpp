#pragma once

namespace tendril::dynamics {

// Lets environments built from a `model` parameter (SmaLimb/LearnedReach-v0) open model files
// and `tendril model fit` run directories (envs::install_dynamics_model_loader with
// load_model). Programs that link this layer call it once at start-up.
void install_model_loader();

}  // namespace tendril::dynamics
