#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tendril/envs/runner/policy_runner.hpp"

namespace tendril::envs {

// The mean per step of the reward and of every info value over a run — the per-step figures the
// beam and UR5 studies quote (distance error, velocity error, energy term). Values in the order
// they first appear.
class StepStatistics : public RunObserver {
 public:
  void on_step(const StepView& step) override;

  int64_t steps() const { return steps_; }
  double mean_reward() const;
  // (name, mean over the steps that reported it).
  std::vector<std::pair<std::string, double>> info_means() const;

 private:
  struct Sum {
    std::string name;
    double total = 0.0;
    int64_t count = 0;
  };
  std::vector<Sum> sums_;
  double reward_total_ = 0.0;
  int64_t steps_ = 0;
};

}  // namespace tendril::envs
