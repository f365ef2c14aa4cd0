#pragma once

#include <memory>

#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// Clips each action component to the inner Box bounds before stepping (Gymnasium's ClipAction):
// Gaussian policies propose unbounded actions; the environment only accepts in-bound ones.
// Unlike Gymnasium, the reported action space stays the inner one, so the policy still sees the
// bounds; values outside them are accepted and clipped. Non-finite values still raise Error.
class ClipAction : public Wrapper {
 public:
  explicit ClipAction(std::unique_ptr<Env> inner);

  Step step(const Action& action) override;
};

}  // namespace tendril::envs
