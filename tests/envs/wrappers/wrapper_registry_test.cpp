#include "tendril/envs/wrappers/wrapper_registry.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/clip_action.hpp"
#include "tendril/envs/wrappers/history_stack.hpp"
#include "tendril/envs/wrappers/rescale_action.hpp"

namespace tendril::envs {
namespace {

using tendril::testing::error_message;

std::unique_ptr<Env> wrapped(const std::string& id, const std::string& yaml) {
  const Config config = Config::parse(yaml, "test.yaml");
  std::unique_ptr<Env> env = apply_wrappers(make(id), config.children("wrappers"));
  config.reject_unknown();
  return env;
}

TEST(WrapperRegistry, AppliesTheListInnermostFirst) {
  auto env =
      wrapped("Pendulum-v1", "wrappers:\n  - history_stack: {length: 4}\n  - rescale_action: {}\n");
  auto* rescale = dynamic_cast<RescaleAction*>(env.get());
  ASSERT_NE(rescale, nullptr);
  auto* history = dynamic_cast<HistoryStack*>(&rescale->inner());
  ASSERT_NE(history, nullptr);
  EXPECT_EQ(history->length(), 4);
  EXPECT_EQ(env->observation_space().size(), 12);  // 4 × Pendulum's (cos θ, sin θ, θ̇)
  EXPECT_EQ(env->action_space().high()(0), 1.0f);  // torque ±2 rescaled to ±1
  // The stack pads with the first observation after reset.
  const Observation first = env->reset(7);
  EXPECT_EQ(first.head(3), first.tail(3));
  EXPECT_NE(find_wrapper<ClipAction>(*wrapped("Pendulum-v1", "wrappers: [{clip_action: {}}]")),
            nullptr);
}

TEST(WrapperRegistry, NoListLeavesTheEnvironmentAlone) {
  auto env = wrapped("Pendulum-v1", "wrappers: []\n");
  EXPECT_EQ(find_wrapper<HistoryStack>(*env), nullptr);
  EXPECT_EQ(env->observation_space().size(), 3);
}

TEST(WrapperRegistry, BadEntriesAreErrorsNamingTheirKey) {
  const auto message = [](const std::string& yaml) {
    return error_message([&] { wrapped("Pendulum-v1", yaml); });
  };
  const std::string unknown = message("wrappers: [{clip_action: {}}, {histroy_stack: {}}]");
  EXPECT_NE(unknown.find("test.yaml: wrappers[1].histroy_stack"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown wrapper 'histroy_stack'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("history_stack"), std::string::npos) << unknown;  // the known names

  const std::string key = message("wrappers: [{history_stack: {length: 2, lenght: 3}}]");
  EXPECT_NE(key.find("wrappers[0].history_stack.lenght"), std::string::npos) << key;

  const std::string value = message("wrappers: [{history_stack: {length: 0}}]");
  EXPECT_NE(value.find("test.yaml: wrappers[0].history_stack.length"), std::string::npos) << value;
  EXPECT_NE(value.find("got 0"), std::string::npos) << value;

  const std::string type = message("wrappers: [{history_stack: {length: four}}]");
  EXPECT_NE(type.find("wrappers[0].history_stack.length"), std::string::npos) << type;

  const std::string missing = message("wrappers: [{history_stack: {}}]");
  EXPECT_NE(missing.find("wrappers[0].history_stack.length"), std::string::npos) << missing;

  const std::string two = message("wrappers: [{clip_action: {}, rescale_action: {}}]");
  EXPECT_NE(two.find("test.yaml: wrappers[0]"), std::string::npos) << two;
  EXPECT_NE(two.find("one name"), std::string::npos) << two;

  EXPECT_NE(message("wrappers: [clip_action]").find("wrappers[0]"), std::string::npos);
  EXPECT_NE(message("wrappers: {clip_action: {}}").find("wrappers"), std::string::npos);
}

TEST(WrapperRegistry, AnEnvironmentTheWrapperCannotTakeIsNamedByItsEntry) {
  // CartPole's actions are Discrete: no Box to clip.
  const Config config = Config::parse("wrappers: [{clip_action: {}}]", "test.yaml");
  const std::string message =
      error_message([&] { apply_wrappers(make("CartPole-v1"), config.children("wrappers")); });
  EXPECT_NE(message.find("test.yaml: wrappers[0].clip_action"), std::string::npos) << message;
  EXPECT_NE(message.find("Box"), std::string::npos) << message;
}

TEST(WrapperRegistry, SnapshotsPassThroughTheWrappers) {
  auto env = wrapped("Pendulum-v1", "wrappers: [{history_stack: {length: 3}}]");
  ASSERT_TRUE(env->supports_snapshots());
  env->reset(1);
  const Action action = Action::Constant(1, 0.5f);
  for (int i = 0; i < 5; ++i) env->step(action);
  Snapshot bytes;
  SnapshotWriter writer(bytes);
  env->save_state(writer);
  std::vector<Observation> original;
  for (int i = 0; i < 4; ++i) original.push_back(env->step(action).observation);
  // Into a copy never reset (as a resumed run's environments are).
  auto restored = wrapped("Pendulum-v1", "wrappers: [{history_stack: {length: 3}}]");
  SnapshotReader reader(bytes);
  restored->load_state(reader);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(restored->step(action).observation, original[i]) << i;
}

}  // namespace
}  // namespace tendril::envs
