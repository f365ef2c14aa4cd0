#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string_view>

#include "tendril/rl/observer.hpp"

namespace tendril::safety::testing {

// One hand-made vector-env step of one environment, x → x' under action u, as the observers of
// a learner (co-trainer, cost critic) see it.
struct OneStep {
  envs::BatchMatrix observations, actions;
  envs::VecStep step;

  OneStep(const Eigen::VectorXf& x, const Eigen::VectorXf& u, const Eigen::VectorXf& next,
          bool truncated = false)
      : observations(x.transpose()), actions(u.transpose()) {
    step.observations = next.transpose();
    step.final_observations = step.observations;
    step.rewards = Eigen::VectorXf::Zero(1);
    step.terminated = {0};
    step.truncated = {static_cast<uint8_t>(truncated ? 1 : 0)};
    step.infos.resize(1);
  }
  OneStep& info(std::string_view name, double value) {
    step.infos[0].set(name, value);
    return *this;
  }
  rl::StepEvent event(int64_t timesteps) const { return {observations, actions, step, timesteps}; }
};

}  // namespace tendril::safety::testing
