#include "tendril/envs/pneumatic/model_history.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"

namespace tendril::envs::pneumatic {
namespace {

constexpr const char* kWhere = "pneumatic::model_history";

class ModelHistory final : public RobotHistoryModel {
 public:
  explicit ModelHistory(ModelDynamics& model) : model_(model) {}

  void reset(const Eigen::VectorXd& state) override {
    require(state.size() == 9, "the state must have 9 values", kWhere);
    model_.reset_to(state);
  }
  Eigen::VectorXd predict(const Eigen::VectorXd& command) override {
    require(command.size() == 9, "the command must have 9 values", kWhere);
    ChamberVector pressures;
    const ChamberVector normalised = command;
    for (int k = 0; k < 9; ++k) pressures[k] = ReachEnv::pressure_of(normalised[k]);
    return model_.predict_next(pressures);
  }
  void follow(const Eigen::VectorXd& state) override {
    require(state.size() == 9, "the state must have 9 values", kWhere);
    model_.follow(state);
  }

 private:
  ModelDynamics& model_;
};

}  // namespace

std::unique_ptr<RobotHistoryModel> model_history(ModelDynamics& model) {
  return std::make_unique<ModelHistory>(model);
}

}  // namespace tendril::envs::pneumatic
