#include "tendril/envs/identity/identity_box.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs {

std::unique_ptr<Env> IdentityBox::create(const Config& params) {
  Params values;
  values.eps = params.get_or<double>("eps", values.eps);
  return std::make_unique<IdentityBox>(values);
}

IdentityBox::IdentityBox(Params params)
    : space_(Space::box(1, -1.0f, 1.0f)), eps_(static_cast<float>(params.eps)) {
  require(params.eps > 0.0, "eps must be positive, got " + std::to_string(params.eps),
          "IdentityBox-v0");
}

Observation IdentityBox::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  state_ = space_.sample(rng_)[0];
  return Observation::Constant(1, state_);
}

Step IdentityBox::step(const Action& action) {
  check_action(space_, action, "IdentityBox-v0");
  Step result;
  // SB3 compares in float32: s − eps ≤ a ≤ s + eps.
  result.reward = state_ - eps_ <= action[0] && action[0] <= state_ + eps_ ? 1.0 : 0.0;
  state_ = space_.sample(rng_)[0];
  result.observation = Observation::Constant(1, state_);
  return result;
}

void IdentityBox::save_state(SnapshotWriter& out) const {
  out.section("IdentityBox");
  out.put(rng_);
  out.put(static_cast<double>(state_));
}

void IdentityBox::load_state(SnapshotReader& in) {
  in.section("IdentityBox");
  Rng rng = rng_;
  in.get(rng);
  const auto state = static_cast<float>(in.get_double());
  rng_ = rng;
  state_ = state;
}

EnvDescription IdentityBox::description() {
  return {
      .observation = {{"state s, uniform in [−1, 1]", "1"}},
      .action = {{"the value a to match s", "1"}},
      .reward = "1 when s − eps ≤ a ≤ s + eps, else 0 (Stable-Baselines3's IdentityEnvBox)",
      .episode_end = "never terminates; truncated by the time limit",
      .parameters = {{"eps", "1", "half-width of the rewarded interval around the state"}},
  };
}

}  // namespace tendril::envs
