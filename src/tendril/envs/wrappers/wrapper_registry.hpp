#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/core/env.hpp"

namespace tendril::envs {

// The wrappers an experiment can list around its environment (Gymnasium's
// EnvSpec.additional_wrappers), applied in order, the first innermost:
//
//   env:
//     id: Pendulum-v1
//     wrappers:
//       - history_stack: {length: 4}   # HistoryStack
//       - clip_action: {}              # ClipAction
//       - rescale_action: {}           # RescaleAction
//
// Each entry is a mapping of one wrapper name to that wrapper's own keys. An unknown name, a key
// the wrapper does not read, a bad value or an environment the wrapper cannot wrap raises Error
// naming the entry's key path (e.g. "env.wrappers[0].history_stack.length").
std::unique_ptr<Env> apply_wrappers(std::unique_ptr<Env> env, const std::vector<Config>& wrappers);

// Sorted names `apply_wrappers` accepts.
std::vector<std::string> wrapper_names();

}  // namespace tendril::envs
