#include "tendril/envs/sma_limb/learned_reach_batch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/envs/sma_limb/reach_observation.hpp"

namespace tendril::envs::sma_limb {

namespace {

constexpr const char* kWhere = "SmaLimb/LearnedReach-v0";
constexpr int kStateDim = 4;
constexpr int kInputDim = 2;

}  // namespace

LearnedReachBatch::LearnedReachBatch(std::shared_ptr<DynamicsModel> model,
                                     LearnedReachOptions options, int num_envs, uint64_t seed)
    : model_(std::move(model)),
      options_(options),
      windows_(std::max(num_envs, 1), model_ ? model_->window_length() : 1, kStateDim, kInputDim),
      inputs_(BatchMatrix::Zero(std::max(num_envs, 1), kInputDim)) {
  require(model_ != nullptr, "needs a dynamics model", kWhere);
  require(num_envs >= 1, "needs at least one environment", kWhere);
  require(model_->state_dim() == kStateDim && model_->input_dim() == kInputDim,
          "needs a model of the limb's 4 states (θx, θy, θ̇x, θ̇y) and 2 throttles, got " +
              std::to_string(model_->state_dim()) + " states and " +
              std::to_string(model_->input_dim()) + " inputs",
          kWhere);
  options_.validate(kWhere);
  require(options_.history <= model_->window_length(),
          "history of " + std::to_string(options_.history) +
              " rows exceeds the model's window of " + std::to_string(model_->window_length()),
          kWhere);
  tasks_.resize(num_envs);
  for (int i = 0; i < num_envs; ++i) {
    tasks_[i].rng = Rng(seed + static_cast<uint64_t>(i));
    tasks_[i].power = PowerProxy(options_.power);
    start_info(tasks_[i]);
  }
}

Space LearnedReachBatch::observation_space() const {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  Eigen::VectorXf low(observation_size()), high(observation_size());
  // A model may predict any state; episodes end once it leaves ±bound.
  low.head<4>().setConstant(-kInf);
  high.head<4>().setConstant(kInf);
  low.segment<2>(4).setConstant(-static_cast<float>(kMaxThrottle));
  high.segment<2>(4).setConstant(static_cast<float>(kMaxThrottle));
  low.segment<2>(6).setConstant(-static_cast<float>(options_.goal_angle_range));
  high.segment<2>(6).setConstant(static_cast<float>(options_.goal_angle_range));
  low.segment<2>(8).setConstant(-static_cast<float>(options_.goal_velocity_range));
  high.segment<2>(8).setConstant(static_cast<float>(options_.goal_velocity_range));
  if (options_.power_proxy) {
    low.segment<4>(10).setZero();
    high.segment<4>(10).setConstant(
        static_cast<float>(PowerProxy(options_.power).bound(kMaxThrottle)));
  }
  const int base = options_.power_proxy ? 14 : 10;
  for (int k = 0; k < options_.history; ++k) {
    low.segment<4>(base + 6 * k).setConstant(-kInf);
    high.segment<4>(base + 6 * k).setConstant(kInf);
    low.segment<2>(base + 6 * k + 4).setConstant(-static_cast<float>(kMaxThrottle));
    high.segment<2>(base + 6 * k + 4).setConstant(static_cast<float>(kMaxThrottle));
  }
  return Space::box(low, high);
}

Space LearnedReachBatch::action_space() {
  return Space::box(kInputDim, -static_cast<float>(kMaxThrottle), static_cast<float>(kMaxThrottle));
}

void LearnedReachBatch::check_env(int env) const {
  if (env < 0 || env >= num_envs()) {
    throw Error(
        "env index " + std::to_string(env) + " outside [0, " + std::to_string(num_envs()) + ")",
        kWhere);
  }
}

void LearnedReachBatch::draw_goal(Task& task) {
  const double angle = options_.goal_angle_range;
  const double velocity = options_.goal_velocity_range;
  task.goal << task.rng.uniform(-angle, angle), task.rng.uniform(-angle, angle),
      task.rng.uniform(-velocity, velocity), task.rng.uniform(-velocity, velocity);
}

void LearnedReachBatch::start_info(Task& task) {
  task.reward = 0.0;
  task.terminated = false;
  task.info.set("distance_deg", 0.0);
  task.info.set("tolerance_deg", options_.tolerance.at(task.simulated_steps));
  task.info.set(info_keys::kIsSuccess, 0.0);
  task.info.set("out_of_bounds", 0.0);
  task.info.set(info_keys::kNan, 0.0);
  task.info.set("full_reset", task.full_reset ? 1.0 : 0.0);
  task.info.set("u_x", task.throttles.x());
  task.info.set("u_y", task.throttles.y());
}

void LearnedReachBatch::reset(int env, std::optional<uint64_t> seed) {
  check_env(env);
  Task& task = tasks_[env];
  if (seed) task.rng = Rng(*seed);
  // The draw is made on every unseeded reset so the stream does not depend on why it was full.
  const bool lucky = task.rng.uniform() < options_.full_reset_probability;
  task.full_reset = seed.has_value() || task.needs_full_reset || lucky;
  if (task.full_reset) {
    const double angle = options_.start_angle_range;
    const double velocity = options_.start_velocity_range;
    Eigen::VectorXf start(kStateDim);
    start << static_cast<float>(task.rng.uniform(-angle, angle)),
        static_cast<float>(task.rng.uniform(-angle, angle)),
        static_cast<float>(task.rng.uniform(-velocity, velocity)),
        static_cast<float>(task.rng.uniform(-velocity, velocity));
    windows_.reset(env, start);
    task.throttles.setZero();
    task.needs_full_reset = false;
  }
  draw_goal(task);
  task.power.reset();
  start_info(task);
  task.info.set("distance_deg", (state(env).head<2>() - task.goal.head<2>()).norm());
}

void LearnedReachBatch::step(const BatchMatrix& actions) {
  require(actions.rows() == num_envs() && actions.cols() == kInputDim,
          "step needs " + std::to_string(num_envs()) + " × 2 throttles, got " +
              std::to_string(actions.rows()) + " × " + std::to_string(actions.cols()),
          kWhere);
  require(actions.allFinite(), "step needs finite throttles", kWhere);
  for (int i = 0; i < num_envs(); ++i) {
    for (int axis = 0; axis < kInputDim; ++axis) {
      double throttle = actions(i, axis);
      if (options_.integer_throttles) throttle = std::round(throttle);
      throttle = std::clamp(throttle, -kMaxThrottle, kMaxThrottle);
      tasks_[i].throttles[axis] = throttle;
      inputs_(i, axis) = static_cast<float>(throttle);
    }
  }
  model_->step(windows_, inputs_, next_states_);
  for (int i = 0; i < num_envs(); ++i) {
    Task& task = tasks_[i];
    task.power.update(task.throttles.x(), task.throttles.y());
    ++task.simulated_steps;
    const double tolerance = options_.tolerance.at(task.simulated_steps);
    const Eigen::Vector4d next = next_states_.row(i).cast<double>().transpose();
    const bool finite = next.allFinite();
    const ReachOutcome outcome =
        reach_outcome(next, task.goal, task.throttles, tolerance, options_.bound);
    task.reward = finite ? outcome.reward : -kBoundsPenalty;
    task.terminated = outcome.reached || outcome.out_of_bounds || !finite;
    if (outcome.out_of_bounds || !finite) task.needs_full_reset = true;
    task.info.set("distance_deg", finite ? outcome.distance_deg : 0.0);
    task.info.set("tolerance_deg", tolerance);
    task.info.set(info_keys::kIsSuccess, outcome.reached ? 1.0 : 0.0);
    task.info.set("out_of_bounds", outcome.out_of_bounds && finite ? 1.0 : 0.0);
    task.info.set(info_keys::kNan, finite ? 0.0 : 1.0);
    task.info.set("full_reset", task.full_reset ? 1.0 : 0.0);
    task.info.set("u_x", task.throttles.x());
    task.info.set("u_y", task.throttles.y());
  }
}

void LearnedReachBatch::observe(int env, Eigen::Ref<Eigen::VectorXf> out) const {
  check_env(env);
  require(out.size() == observation_size(), "observation buffer of the wrong size", kWhere);
  const Task& task = tasks_[env];
  // A non-finite prediction ends the episode; the observation keeps finite values.
  write_reach_observation(windows_, env, task.throttles, task.goal,
                          options_.power_proxy ? &task.power : nullptr, options_.history, out);
}

Eigen::Vector4d LearnedReachBatch::state(int env) const {
  check_env(env);
  return windows_.state(env).cast<double>();
}

void LearnedReachBatch::set_goal(int env, const Eigen::Vector4d& goal) {
  check_env(env);
  require(goal.allFinite(), "goal must be finite", kWhere);
  tasks_[env].goal = goal;
}

double LearnedReachBatch::tolerance(int env) const {
  check_env(env);
  return options_.tolerance.at(tasks_[env].simulated_steps);
}

void LearnedReachBatch::save_state(SnapshotWriter& out) const {
  out.section(kWhere);
  out.put(static_cast<int64_t>(num_envs()));
  windows_.save_state(out);
  for (const Task& task : tasks_) {
    out.put(task.rng);
    out.put_matrix(task.goal);
    task.power.save_state(out);
    out.put_matrix(task.throttles);
    out.put(task.simulated_steps);
    out.put(task.needs_full_reset);
    out.put(task.full_reset);
    out.put(task.reward);
    out.put(task.terminated);
    for (const auto& entry : task.info.entries()) out.put(entry.second);
  }
}

void LearnedReachBatch::load_state(SnapshotReader& in) {
  in.section(kWhere);
  const int64_t count = in.get_int64();
  require(
      count == num_envs(),
      "snapshot of " + std::to_string(count) + " environments, not " + std::to_string(num_envs()),
      kWhere);
  HistoryWindows windows = windows_;
  windows.load_state(in);
  std::vector<Task> tasks = tasks_;
  for (Task& task : tasks) {
    in.get(task.rng);
    in.get_matrix(task.goal);
    task.power.load_state(in);
    in.get_matrix(task.throttles);
    task.simulated_steps = in.get_int64();
    task.needs_full_reset = in.get_bool();
    task.full_reset = in.get_bool();
    task.reward = in.get_double();
    task.terminated = in.get_bool();
    Info info;
    for (const auto& entry : task.info.entries()) info.set(entry.first, in.get_double());
    task.info = std::move(info);
  }
  windows_ = std::move(windows);
  tasks_ = std::move(tasks);
}

}  // namespace tendril::envs::sma_limb
