#include "tendril/safety/co_trainer.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <sstream>

#include "tendril/core/error.hpp"

namespace tendril::safety {

SafetyCoTrainer::SafetyCoTrainer(rl::OffPolicyAlgorithm& safety_agent,
                                 const envs::SafetyConstraint& constraint,
                                 const SafetyReward& reward, const CoTrainingSettings& settings,
                                 int64_t total_timesteps, uint64_t seed)
    : agent_(safety_agent),
      constraint_(constraint),
      reward_(reward),
      settings_(settings),
      total_timesteps_(total_timesteps),
      action_space_(safety_agent.policy().action_space()),
      buffer_(settings.buffer_size, safety_agent.policy().observation_space().size(),
              action_space_.size()),
      rng_(seed) {
  require(settings.train_freq > 0 && settings.gradient_steps >= 0 &&
              settings.unsafe_samples_per_step >= 0 && total_timesteps > 0,
          "train_freq and total_timesteps must be positive, the counts non-negative",
          "SafetyCoTrainer");
}

Action SafetyCoTrainer::agent_action(const Eigen::Ref<const Eigen::VectorXf>& action) const {
  // Off-policy agents store Box actions in [−1, 1].
  Eigen::MatrixXf stored = action;
  rl::unscale_from_bounds(action_space_, stored);
  return stored.col(0);
}

void SafetyCoTrainer::store(const Eigen::Ref<const Eigen::VectorXf>& observation,
                            const Action& action, double reward,
                            const Eigen::Ref<const Eigen::VectorXf>& next_observation,
                            bool terminated) {
  buffer_.add(observation, action, static_cast<float>(reward), next_observation, terminated);
  ++stored_;
}

void SafetyCoTrainer::on_step(const rl::StepEvent& event) {
  const auto num_envs = static_cast<int>(event.observations.rows());
  if (gate_open_.empty()) gate_open_.assign(num_envs, 1);
  for (int i = 0; i < num_envs; ++i) {
    if (gate_open_[i] != 0) {
      const Observation x = event.observations.row(i).transpose();
      const Observation next = event.step.final_observations.row(i).transpose();
      const bool unsafe = constraint_.unsafe(x);
      const bool next_unsafe = constraint_.unsafe(next);
      const double level = SafetyReward::level(constraint_.margin(x), constraint_.max_margin());
      const double r = reward_.reward(level, constraint_.time_step(x), unsafe, next_unsafe);
      // The safety agent's episode ends on entering X_unsafe and at the maximum length T
      // (§6.2.1): with t in the state its problem has a finite horizon, so the time limit is a
      // termination, not a truncation to bootstrap through (V beyond T is 0, the bound
      // (1 − γ^{T+1})/(1 − γ) of §6.2.2).
      const bool terminated = unsafe || next_unsafe || event.step.done(i);
      const auto& actions =
          filtered_env_ != nullptr ? filtered_env_->executed_actions() : event.actions;
      store(x, agent_action(actions.row(i).transpose()), r, next, terminated);
      if (unsafe || next_unsafe) {
        gate_open_[i] = 0;
        ++unsafe_entries_;
      }
      for (int64_t k = 0; k < settings_.unsafe_samples_per_step; ++k) {
        const Observation sample = constraint_.sample_unsafe(rng_);
        Action action(action_space_.size());
        if (action_space_.is_discrete()) {
          action[0] = static_cast<float>(rng_.below(action_space_.n()));
        } else {
          for (Eigen::Index j = 0; j < action.size(); ++j) {
            action[j] = static_cast<float>(rng_.uniform(-1.0, 1.0));
          }
        }
        buffer_.add(sample, action, static_cast<float>(reward_.unsafe_target()), sample, true);
      }
    } else {
      ++gated_;
    }
    if (event.step.done(i)) gate_open_[i] = 1;
  }
  ++steps_;
  agent_.count_external_step(event.timesteps, total_timesteps_);
  if (steps_ % settings_.train_freq == 0 && stored_ >= settings_.learning_starts &&
      settings_.gradient_steps > 0) {
    const double remaining = std::clamp(
        1.0 - static_cast<double>(event.timesteps) / static_cast<double>(total_timesteps_), 0.0,
        1.0);
    last_stats_ = agent_.train_on(buffer_, settings_.gradient_steps, remaining);
  }
}

void SafetyCoTrainer::save(ArchiveWriter& writer, const std::string& prefix) const {
  writer.put_bytes(prefix + "buffer", std::as_bytes(std::span<const char>(buffer_.serialize())));
  writer.put_rng(prefix + "rng", rng_);
  writer.put_bytes(prefix + "gates", std::as_bytes(std::span<const uint8_t>(gate_open_)));
  writer.put(prefix + "steps", steps_);
  writer.put(prefix + "stored", stored_);
  writer.put(prefix + "gated", gated_);
  writer.put(prefix + "unsafe_entries", unsafe_entries_);
  std::string names;
  std::vector<double> values;
  for (const auto& [name, value] : last_stats_) {
    names += name + "\n";
    values.push_back(value);
  }
  writer.put(prefix + "stat_names", names);
  writer.put_doubles(prefix + "stat_values", values);
}

std::function<void()> SafetyCoTrainer::prepare_load(const ArchiveReader& reader,
                                                    const std::string& prefix) {
  const std::string where = reader.name() + " (" + prefix + ")";
  const Snapshot buffer_bytes = reader.get_bytes(prefix + "buffer");
  auto buffer = std::make_shared<rl::ReplayBuffer>(buffer_.capacity(), buffer_.observation_size(),
                                                   buffer_.action_size());
  buffer->load_bytes(
      std::string(reinterpret_cast<const char*>(buffer_bytes.data()), buffer_bytes.size()), where);
  const Rng rng = reader.get_rng(prefix + "rng");
  const Snapshot gate_bytes = reader.get_bytes(prefix + "gates");
  std::vector<uint8_t> gates(gate_bytes.size());
  for (std::size_t i = 0; i < gates.size(); ++i) {
    gates[i] = static_cast<uint8_t>(gate_bytes[i]);
    require(gates[i] <= 1, "a gate is neither open nor closed", where);
  }
  const int64_t steps = reader.get_int(prefix + "steps");
  const int64_t stored = reader.get_int(prefix + "stored");
  const int64_t gated = reader.get_int(prefix + "gated");
  const int64_t unsafe_entries = reader.get_int(prefix + "unsafe_entries");
  require(steps >= 0 && stored >= 0 && gated >= 0 && unsafe_entries >= 0, "negative counts", where);
  std::istringstream names(reader.get_string(prefix + "stat_names"));
  const std::vector<double> values = reader.get_doubles(prefix + "stat_values");
  rl::TrainStats stats;
  for (std::string name; std::getline(names, name);) {
    require(stats.size() < values.size(), "more scalar names than values", where);
    stats.emplace_back(name, values[stats.size()]);
  }
  require(stats.size() == values.size(), "more scalar values than names", where);
  return [this, buffer, rng, gates, steps, stored, gated, unsafe_entries, stats] {
    buffer_ = std::move(*buffer);
    rng_ = rng;
    gate_open_ = gates;
    steps_ = steps;
    stored_ = stored;
    gated_ = gated;
    unsafe_entries_ = unsafe_entries;
    last_stats_ = stats;
  };
}

}  // namespace tendril::safety
