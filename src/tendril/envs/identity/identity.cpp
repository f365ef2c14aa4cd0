#include "tendril/envs/identity/identity.hpp"

#include "tendril/core/error.hpp"

namespace tendril::envs {

std::unique_ptr<Env> Identity::create(const Config& params) {
  Params values;
  values.n = params.get_or<int64_t>("n", values.n);
  return std::make_unique<Identity>(values);
}

namespace {

int64_t checked_size(int64_t n) {
  // One-hot observations are floats, which hold every integer index exactly up to 2^24.
  require(n >= 1 && n <= (int64_t{1} << 24), "n must lie in [1, 2^24], got " + std::to_string(n),
          "Identity-v0");
  return n;
}

}  // namespace

Identity::Identity(Params params)
    : observation_space_(Space::box(static_cast<int>(checked_size(params.n)), 0.0f, 1.0f)),
      action_space_(Space::discrete(params.n)) {}

Observation Identity::reset(std::optional<uint64_t> seed) {
  if (seed) rng_ = Rng(*seed);
  state_ = static_cast<int64_t>(rng_.below(static_cast<uint64_t>(action_space_.n())));
  return observe();
}

Step Identity::step(const Action& action) {
  check_action(action_space_, action, "Identity-v0");
  Step result;
  result.reward = static_cast<int64_t>(action[0]) == state_ ? 1.0 : 0.0;
  state_ = static_cast<int64_t>(rng_.below(static_cast<uint64_t>(action_space_.n())));
  result.observation = observe();
  return result;
}

Observation Identity::observe() const {
  Observation one_hot = Observation::Zero(action_space_.n());
  one_hot[state_] = 1.0f;
  return one_hot;
}

void Identity::save_state(SnapshotWriter& out) const {
  out.section("Identity");
  out.put(rng_);
  out.put(static_cast<int64_t>(state_));
}

void Identity::load_state(SnapshotReader& in) {
  in.section("Identity");
  Rng rng = rng_;
  in.get(rng);
  const int64_t state = in.get_int64();
  rng_ = rng;
  state_ = state;
}

EnvDescription Identity::description() {
  return {
      .observation = {{"one-hot state: entry i is 1 for state i, 0..n−1", "1",
                       static_cast<int>(Params{}.n)}},
      .action = {{"the state index to repeat, 0..n−1", "1"}},
      .reward =
          "1 when the action equals the state of the step, else 0 (Stable-Baselines3's "
          "IdentityEnv)",
      .episode_end = "never terminates; truncated by the time limit",
      .parameters = {{"n", "", "number of states and actions (sets both spaces' sizes)"}},
  };
}

}  // namespace tendril::envs
