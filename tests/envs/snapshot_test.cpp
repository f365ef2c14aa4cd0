// Every registered environment that supports snapshots is checked here: stepping on from a
// loaded snapshot repeats the original steps exactly, and a foreign snapshot is refused. New
// environments are covered by registering them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "support/required_env_params.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs {
namespace {

Action random_action(const Space& space, Rng& rng) {
  Action action(space.size());
  if (space.is_discrete()) {
    action[0] = static_cast<float>(rng.below(static_cast<uint64_t>(space.n())));
    return action;
  }
  for (int i = 0; i < space.size(); ++i) {
    const double low = std::max(-1.0, static_cast<double>(space.low()[i]));
    const double high = std::min(1.0, static_cast<double>(space.high()[i]));
    action[i] = static_cast<float>(rng.uniform(low, high));
  }
  return action;
}

struct Trace {
  std::vector<Observation> observations;
  std::vector<double> rewards;
  std::vector<std::vector<std::pair<std::string, double>>> infos;
  std::vector<int> ends;  // 0 running, 1 terminated, 2 truncated
};

// Steps `env` with `actions`, resetting (without a seed: the env's own stream continues) where
// an episode ends, as a vector env would.
Trace run(Env& env, const std::vector<Action>& actions) {
  Trace trace;
  for (const Action& action : actions) {
    Step step = env.step(action);
    trace.rewards.push_back(step.reward);
    trace.infos.push_back(step.info.entries());
    trace.ends.push_back(step.terminated ? 1 : step.truncated ? 2 : 0);
    if (step.terminated || step.truncated) step.observation = env.reset();
    trace.observations.push_back(step.observation);
  }
  return trace;
}

std::unique_ptr<Env> make_env(const std::string& id) {
  return make(id, testing::required_env_params(id));
}

class EverySnapshotEnv : public ::testing::TestWithParam<std::string> {};

TEST_P(EverySnapshotEnv, SteppingOnFromALoadedSnapshotRepeatsTheOriginal) {
  const std::string id = GetParam();
  auto original = make_env(id);
  if (!original->supports_snapshots()) {
    Snapshot bytes;
    SnapshotWriter out(bytes);
    EXPECT_NE(testing::error_message([&] { original->save_state(out); }), "no error") << id;
    return;
  }
  Rng rng(11);
  original->reset(3);
  std::vector<Action> warm_up, after;
  for (int i = 0; i < 40; ++i) warm_up.push_back(random_action(original->action_space(), rng));
  for (int i = 0; i < 60; ++i) after.push_back(random_action(original->action_space(), rng));
  run(*original, warm_up);

  Snapshot bytes;
  SnapshotWriter out(bytes);
  original->save_state(out);
  auto copy = make_env(id);
  copy->reset(99);  // another episode entirely
  SnapshotReader in(bytes);
  copy->load_state(in);
  EXPECT_TRUE(in.at_end()) << id;

  const Trace expected = run(*original, after);
  const Trace actual = run(*copy, after);
  EXPECT_EQ(actual.rewards, expected.rewards) << id;
  EXPECT_EQ(actual.ends, expected.ends) << id;
  EXPECT_EQ(actual.infos, expected.infos) << id;
  ASSERT_EQ(actual.observations.size(), expected.observations.size());
  for (size_t t = 0; t < expected.observations.size(); ++t) {
    ASSERT_EQ(actual.observations[t], expected.observations[t]) << id << ", step " << t;
  }
}

TEST_P(EverySnapshotEnv, ASnapshotOfAnotherEnvironmentIsRefused) {
  const std::string id = GetParam();
  auto env = make_env(id);
  if (!env->supports_snapshots()) return;
  env->reset(1);
  // Another registered env that supports snapshots and has another id.
  for (const std::string& other_id : registered_ids()) {
    if (other_id == id) continue;
    auto other = make_env(other_id);
    if (!other->supports_snapshots()) continue;
    other->reset(1);
    Snapshot bytes;
    SnapshotWriter out(bytes);
    other->save_state(out);
    SnapshotReader in(bytes);
    EXPECT_NE(testing::error_message([&] { env->load_state(in); }), "no error")
        << other_id << " loaded into " << id;
    return;
  }
}

INSTANTIATE_TEST_SUITE_P(Registered, EverySnapshotEnv, ::testing::ValuesIn(registered_ids()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace tendril::envs
