#include "tendril/envs/wrappers/curriculum.hpp"

#include <cmath>
#include <numeric>

#include "tendril/core/error.hpp"
#include "tendril/core/log.hpp"

namespace tendril::envs {

CurriculumRule CurriculumRule::from_config(const Config& config) {
  CurriculumRule rule;
  rule.metric = config.get_or<std::string>("metric", rule.metric);
  rule.threshold = config.get_or<double>("threshold", rule.threshold);
  rule.higher_is_better = config.get_or<bool>("higher_is_better", rule.higher_is_better);
  rule.window = config.get_or<int>("window", rule.window);
  rule.success_rate = config.get_or<double>("success_rate", rule.success_rate);
  rule.failed_if_terminated =
      config.get_or<bool>("failed_if_terminated", rule.failed_if_terminated);
  rule.start_level = config.get_or<int>("start_level", rule.start_level);
  const std::string where =
      config.source() + ": " + (config.path().empty() ? "" : config.path() + ".");
  if (config.has("rule")) {
    const std::string name = config.get<std::string>("rule");
    if (name == "success_rate") {
      rule.rule = Rule::kSuccessRate;
    } else if (name == "mean") {
      rule.rule = Rule::kMean;
    } else {
      throw Error("expected success_rate or mean, got '" + name + "'", where + "rule");
    }
  }
  rule.validate(where.empty() ? "curriculum" : where.substr(0, where.size() - 1));
  return rule;
}

void CurriculumRule::validate(const std::string& where) const {
  require(!metric.empty(), "metric must name an info value", where);
  require(std::isfinite(threshold), "threshold must be finite", where);
  require(window >= 1, "window must be at least 1, got " + std::to_string(window), where);
  require(success_rate > 0.0 && success_rate <= 1.0, "success_rate must lie in (0, 1]", where);
  require(start_level >= 0, "start_level must be non-negative", where);
}

Curriculum::Curriculum(std::unique_ptr<Env> inner, const CurriculumRule& rule)
    : Wrapper(std::move(inner)), task_(dynamic_cast<CurriculumTask*>(inner_.get())), rule_(rule) {
  require(task_ != nullptr, "this environment has no curriculum levels", "envs::Curriculum");
  rule_.validate("envs::Curriculum");
  require(rule_.start_level < task_->curriculum_levels(),
          "start_level " + std::to_string(rule_.start_level) + " is not one of the task's " +
              std::to_string(task_->curriculum_levels()) + " levels",
          "envs::Curriculum");
  task_->set_curriculum_level(rule_.start_level);
}

Observation Curriculum::reset(std::optional<uint64_t> seed) {
  if (steps_ > 0) finish_episode();
  return inner_->reset(seed);
}

Step Curriculum::step(const Action& action) {
  Step result = inner_->step(action);
  const std::optional<double> value = result.info.get(rule_.metric);
  if (!value) {
    throw Error("the environment reports no info value '" + rule_.metric + "'",
                "envs::Curriculum metric");
  }
  metric_sum_ += *value;
  ++steps_;
  terminated_ = result.terminated;
  result.info.set(kLevelKey, level());
  if (result.terminated) finish_episode();
  return result;
}

void Curriculum::finish_episode() {
  const double score = metric_sum_ / static_cast<double>(steps_);
  const bool beats = rule_.higher_is_better ? score > rule_.threshold : score < rule_.threshold;
  const bool success = beats && !(rule_.failed_if_terminated && terminated_);
  metric_sum_ = 0.0;
  steps_ = 0;
  terminated_ = false;
  scores_.push_back(score);
  successes_.push_back(success ? 1 : 0);
  if (static_cast<int>(scores_.size()) > rule_.window) {
    scores_.pop_front();
    successes_.pop_front();
  }
  ++episodes_at_level_;
  if (level() + 1 >= levels() || static_cast<int>(scores_.size()) < rule_.window) return;
  bool promote = false;
  if (rule_.rule == CurriculumRule::Rule::kSuccessRate) {
    const double rate = std::accumulate(successes_.begin(), successes_.end(), 0.0) / rule_.window;
    promote = rate >= rule_.success_rate;
  } else {
    const double mean = std::accumulate(scores_.begin(), scores_.end(), 0.0) / rule_.window;
    promote = rule_.higher_is_better ? mean > rule_.threshold : mean < rule_.threshold;
  }
  if (!promote) return;
  task_->set_curriculum_level(level() + 1);
  log::info("curriculum: level ", level(), " of ", levels() - 1, " after ", episodes_at_level_,
            " episodes at the previous one");
  scores_.clear();
  successes_.clear();
  episodes_at_level_ = 0;
}

void Curriculum::save_state(SnapshotWriter& out) const {
  out.section("Curriculum");
  out.put(static_cast<int64_t>(level()));
  out.put(episodes_at_level_);
  out.put(static_cast<int64_t>(scores_.size()));
  for (std::size_t i = 0; i < scores_.size(); ++i) {
    out.put(scores_[i]);
    out.put(successes_[i] != 0);
  }
  out.put(metric_sum_);
  out.put(steps_);
  out.put(terminated_);
  inner_->save_state(out);
}

void Curriculum::load_state(SnapshotReader& in) {
  in.section("Curriculum");
  const int64_t level = in.get_int64();
  const int64_t episodes = in.get_int64();
  const int64_t count = in.get_int64();
  if (level < 0 || level >= levels() || count < 0 || count > rule_.window) {
    throw Error("snapshot has level " + std::to_string(level) + " and " + std::to_string(count) +
                    " episodes, which this curriculum cannot hold",
                "envs::Curriculum::load_state");
  }
  std::deque<double> scores;
  std::deque<uint8_t> successes;
  for (int64_t i = 0; i < count; ++i) {
    scores.push_back(in.get_double());
    successes.push_back(in.get_bool() ? 1 : 0);
  }
  const double metric_sum = in.get_double();
  const int64_t steps = in.get_int64();
  const bool terminated = in.get_bool();
  inner_->load_state(in);  // the task's own level comes with its state
  require(task_->curriculum_level() == level, "the task's level disagrees with the curriculum's",
          "envs::Curriculum::load_state");
  episodes_at_level_ = episodes;
  scores_ = std::move(scores);
  successes_ = std::move(successes);
  metric_sum_ = metric_sum;
  steps_ = steps;
  terminated_ = terminated;
}

}  // namespace tendril::envs
