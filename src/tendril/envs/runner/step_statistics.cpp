#include "tendril/envs/runner/step_statistics.hpp"

namespace tendril::envs {

void StepStatistics::on_step(const StepView& step) {
  ++steps_;
  reward_total_ += step.result.reward;
  for (const auto& [name, value] : step.result.info.entries()) {
    Sum* sum = nullptr;
    for (Sum& existing : sums_) {
      if (existing.name == name) sum = &existing;
    }
    if (sum == nullptr) sum = &sums_.emplace_back(Sum{name});
    sum->total += value;
    ++sum->count;
  }
}

double StepStatistics::mean_reward() const {
  return steps_ > 0 ? reward_total_ / static_cast<double>(steps_) : 0.0;
}

std::vector<std::pair<std::string, double>> StepStatistics::info_means() const {
  std::vector<std::pair<std::string, double>> means;
  for (const Sum& sum : sums_) {
    means.emplace_back(sum.name, sum.total / static_cast<double>(sum.count));
  }
  return means;
}

}  // namespace tendril::envs
