// The dynamics layer loaded on demand: once, again after a failed load, not at all without a
// loader.
#include "tendril/core/dynamics_layer.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"

namespace tendril {
namespace {

TEST(DynamicsLayer, WithoutALoaderNothingIsLoaded) {
  set_dynamics_layer_loader({});
  EXPECT_FALSE(load_dynamics_layer());
}

TEST(DynamicsLayer, TheLoaderRunsOnceForEveryLookup) {
  int loads = 0;
  set_dynamics_layer_loader([&] { ++loads; });
  EXPECT_TRUE(load_dynamics_layer());
  EXPECT_TRUE(load_dynamics_layer());
  EXPECT_TRUE(load_dynamics_layer());
  EXPECT_EQ(loads, 1);
  set_dynamics_layer_loader({});
}

TEST(DynamicsLayer, AFailedLoadRaisesAgainAtTheNextLookupAndThenSucceeds) {
  int attempts = 0;
  set_dynamics_layer_loader([&] {
    if (++attempts < 3) throw Error("not found", "plugin.so");
  });
  EXPECT_NE(testing::error_message([] { load_dynamics_layer(); }).find("not found"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] { load_dynamics_layer(); }).find("plugin.so"),
            std::string::npos);
  EXPECT_TRUE(load_dynamics_layer());
  EXPECT_TRUE(load_dynamics_layer());
  EXPECT_EQ(attempts, 3);
  set_dynamics_layer_loader({});
}

}  // namespace
}  // namespace tendril
