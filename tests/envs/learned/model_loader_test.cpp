// How environments open learned models: the installed loader, or the dynamics layer loaded on
// demand at the first model opened; without either, an error naming who asked.
#include "tendril/envs/learned/model_loader.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/dynamics_layer.hpp"

namespace tendril::envs {
namespace {

// A model of `file_or_run`'s length in states: enough to tell which file it came from.
class StandInModel : public DynamicsModel {
 public:
  explicit StandInModel(int states) : states_(states) {}
  int state_dim() const override { return states_; }
  int input_dim() const override { return 1; }
  int window_length() const override { return 1; }
  double sample_period() const override { return 0.1; }
  void predict(const BatchMatrix&, BatchMatrix&) override {}

 private:
  int states_;
};

TEST(ModelLoader, WithoutTheDynamicsLayerOpeningAModelIsAClearError) {
  install_dynamics_model_loader(nullptr);
  set_dynamics_layer_loader({});
  const std::string message =
      testing::error_message([] { load_dynamics_model("runs/m", "env.params.model"); });
  EXPECT_NE(message.find("built without the dynamics layer"), std::string::npos) << message;
  EXPECT_NE(message.find("env.params.model"), std::string::npos) << message;
}

TEST(ModelLoader, TheFirstModelOpenedLoadsTheDynamicsLayerOnceAndUsesItsLoader) {
  install_dynamics_model_loader(nullptr);
  int loads = 0;
  set_dynamics_layer_loader([&] {
    ++loads;
    install_dynamics_model_loader([](const std::string& file_or_run) {
      return std::make_unique<StandInModel>(static_cast<int>(file_or_run.size()));
    });
  });
  EXPECT_EQ(load_dynamics_model("runs/m", "test")->state_dim(), 6);
  EXPECT_EQ(load_dynamics_model("runs/model", "test")->state_dim(), 10);
  EXPECT_EQ(loads, 1);
  set_dynamics_layer_loader({});
  install_dynamics_model_loader(nullptr);
}

TEST(ModelLoader, AnInstalledLoaderNeedsNoLoading) {
  install_dynamics_model_loader(
      [](const std::string&) { return std::make_unique<StandInModel>(4); });
  set_dynamics_layer_loader([] { FAIL() << "the dynamics layer was loaded"; });
  EXPECT_EQ(load_dynamics_model("m.tdm", "test")->state_dim(), 4);
  set_dynamics_layer_loader({});
  install_dynamics_model_loader(nullptr);
}

}  // namespace
}  // namespace tendril::envs
