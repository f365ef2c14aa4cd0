#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "tendril/core/config.hpp"
#include "tendril/envs/curriculum_task.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// When a Curriculum promotes its task to the next level (SPEC M4; seed 003, Sec. VII-B: train
// on fixed parameters first, then widen their ranges level by level). Each finished episode is
// scored by the mean, over its steps, of one info value (`metric`); the episode succeeds when
// that mean is below `threshold` (above it with `higher_is_better`) and, with
// `failed_if_terminated`, it was not ended early by the task (a time limit is not early). Once
// `window` episodes have finished at the current level, the task moves up when
//   rule kSuccessRate: the share of successes among the last `window` episodes ≥ success_rate;
//   rule kMean:        the mean of their scores beats `threshold`.
struct CurriculumRule {
  enum class Rule { kSuccessRate, kMean };
  std::string metric = "distance";
  double threshold = 0.06;
  bool higher_is_better = false;
  int window = 20;
  Rule rule = Rule::kSuccessRate;
  double success_rate = 0.8;
  bool failed_if_terminated = true;
  int start_level = 0;

  // Reads the keys above from an environment's `curriculum` parameters (rule: success_rate or
  // mean); unset keys keep their defaults. Raises Error naming the key of a bad value.
  static CurriculumRule from_config(const Config& config);
  void validate(const std::string& where) const;
};

// Moves a CurriculumTask through its levels by a CurriculumRule. Any registered environment
// whose task implements CurriculumTask gets one from its parameters:
//   env: {id: Beam/EllipseFollow-v0, params: {curriculum: {window: 20, threshold: 0.06}}}
// (Registry::make wraps it inside the time limit). The level changes only at a reset, so an
// episode runs at one level throughout. Every step reports "curriculum_level" in its info.
// Snapshots hold the level and the episodes counted at it, then the task's own state.
//
// Each environment instance keeps its own curriculum: in a VecEnv of n copies each promotes on
// its own episodes, and an evaluation environment built afresh starts at `start_level`.
class Curriculum : public Wrapper {
 public:
  static constexpr const char* kLevelKey = "curriculum_level";

  // Raises Error unless `inner` is a CurriculumTask.
  Curriculum(std::unique_ptr<Env> inner, const CurriculumRule& rule);

  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;
  void save_state(SnapshotWriter& out) const override;
  void load_state(SnapshotReader& in) override;

  int level() const { return task_->curriculum_level(); }
  int levels() const { return task_->curriculum_levels(); }
  const CurriculumRule& rule() const { return rule_; }
  // Episodes finished at the current level, and the scores of the last `window` of them.
  int64_t episodes_at_level() const { return episodes_at_level_; }
  const std::deque<double>& recent_scores() const { return scores_; }

 private:
  void finish_episode();

  CurriculumTask* task_;
  CurriculumRule rule_;
  std::deque<double> scores_;
  std::deque<uint8_t> successes_;
  int64_t episodes_at_level_ = 0;
  double metric_sum_ = 0.0;  // over the episode in progress
  int64_t steps_ = 0;
  bool terminated_ = false;
};

}  // namespace tendril::envs
