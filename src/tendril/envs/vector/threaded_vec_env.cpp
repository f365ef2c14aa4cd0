#include "tendril/envs/vector/threaded_vec_env.hpp"

#include <algorithm>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::envs {

namespace {

constexpr const char* kWhere = "envs::ThreadedVecEnv";

bool same_shape(const Space& a, const Space& b) {
  return a.kind() == b.kind() && a.size() == b.size() && (a.is_box() || a.n() == b.n());
}

std::vector<std::unique_ptr<Env>> build(int num_envs,
                                        const std::function<std::unique_ptr<Env>(int)>& factory) {
  require(num_envs >= 1, "num_envs must be at least 1, got " + std::to_string(num_envs), kWhere);
  std::vector<std::unique_ptr<Env>> envs;
  envs.reserve(num_envs);
  for (int i = 0; i < num_envs; ++i) envs.push_back(factory(i));
  return envs;
}

}  // namespace

ThreadedVecEnv::ThreadedVecEnv(int num_envs,
                               const std::function<std::unique_ptr<Env>(int)>& factory,
                               int num_threads)
    : ThreadedVecEnv(build(num_envs, factory), num_threads) {}

ThreadedVecEnv::ThreadedVecEnv(std::vector<std::unique_ptr<Env>> envs, int num_threads)
    : envs_(std::move(envs)) {
  require(!envs_.empty(), "needs at least one environment", kWhere);
  for (std::size_t i = 0; i < envs_.size(); ++i) {
    require(envs_[i] != nullptr, "environment " + std::to_string(i) + " is null", kWhere);
    require(same_shape(envs_[i]->observation_space(), observation_space()) &&
                same_shape(envs_[i]->action_space(), action_space()),
            "environment " + std::to_string(i) + " has spaces " +
                envs_[i]->observation_space().describe() + " / " +
                envs_[i]->action_space().describe() + ", environment 0 " +
                observation_space().describe() + " / " + action_space().describe(),
            kWhere);
  }
  require(num_threads >= 1, "num_threads must be at least 1, got " + std::to_string(num_threads),
          kWhere);
  const int threads = std::min(num_threads, num_envs());
  if (threads > 1) pool_ = std::make_unique<ThreadPool>(threads);

  const int n = num_envs();
  const int observation_size = observation_space().size();
  actions_.assign(n, Action::Zero(action_space().size()));
  errors_.assign(n, nullptr);
  next_reset_seeds_.assign(n, std::nullopt);
  result_.observations = BatchMatrix::Zero(n, observation_size);
  result_.final_observations = BatchMatrix::Zero(n, observation_size);
  result_.rewards = Eigen::VectorXf::Zero(n);
  result_.terminated.assign(n, 0);
  result_.truncated.assign(n, 0);
  result_.infos.assign(n, Info{});
}

void ThreadedVecEnv::for_each_env(const std::function<void(int)>& task) {
  // Every env runs even if another fails; then the lowest failing index's error is rethrown,
  // so the error a caller sees does not depend on thread scheduling.
  const auto guarded = [&](int i) {
    try {
      task(i);
    } catch (...) {
      errors_[i] = std::current_exception();
    }
  };
  std::fill(errors_.begin(), errors_.end(), nullptr);
  if (pool_) {
    pool_->run(num_envs(), guarded);
  } else {
    for (int i = 0; i < num_envs(); ++i) guarded(i);
  }
  for (const auto& error : errors_) {
    if (error) {
      ready_ = false;
      std::rethrow_exception(error);
    }
  }
}

const BatchMatrix& ThreadedVecEnv::reset(std::optional<uint64_t> seed) {
  std::fill(next_reset_seeds_.begin(), next_reset_seeds_.end(), std::nullopt);
  const int observation_size = observation_space().size();
  for_each_env([&](int i) {
    const std::optional<uint64_t> env_seed =
        seed ? std::optional<uint64_t>(*seed + static_cast<uint64_t>(i)) : std::nullopt;
    const Observation observation = envs_[i]->reset(env_seed);
    require(observation.size() == observation_size,
            "environment " + std::to_string(i) + " returned " + std::to_string(observation.size()) +
                " observation components, expected " + std::to_string(observation_size),
            kWhere);
    result_.observations.row(i) = observation.transpose();
  });
  ready_ = true;
  return result_.observations;
}

void ThreadedVecEnv::seed_next_reset(int env, uint64_t seed) {
  require(env >= 0 && env < num_envs(), "no environment " + std::to_string(env), kWhere);
  next_reset_seeds_[env] = seed;
}

void ThreadedVecEnv::step_one(int i) {
  Step step = envs_[i]->step(actions_[i]);
  if (step.observation.size() != result_.observations.cols()) {
    throw Error("environment " + std::to_string(i) + " returned " +
                    std::to_string(step.observation.size()) + " observation components, expected " +
                    std::to_string(result_.observations.cols()),
                kWhere);
  }
  result_.final_observations.row(i) = step.observation.transpose();
  result_.rewards[i] = static_cast<float>(step.reward);
  result_.terminated[i] = step.terminated ? 1 : 0;
  result_.truncated[i] = step.truncated ? 1 : 0;
  if (step.terminated || step.truncated) {
    // Auto-reset without a seed (unless seed_next_reset gave one): the env continues its own
    // random stream, so the whole run stays determined by the seed given to reset().
    result_.observations.row(i) = envs_[i]->reset(next_reset_seeds_[i]).transpose();
    next_reset_seeds_[i].reset();
  } else {
    result_.observations.row(i) = step.observation.transpose();
  }
  result_.infos[i] = std::move(step.info);
}

const VecStep& ThreadedVecEnv::step(const BatchMatrix& actions) {
  require(ready_, "step called before reset (or after an environment error)", kWhere);
  if (actions.rows() != num_envs() || actions.cols() != action_space().size()) {
    throw Error("actions are " + std::to_string(actions.rows()) + " x " +
                    std::to_string(actions.cols()) + ", expected " + std::to_string(num_envs()) +
                    " x " + std::to_string(action_space().size()) + " (envs x action size)",
                kWhere);
  }
  for (int i = 0; i < num_envs(); ++i) actions_[i] = actions.row(i).transpose();
  for_each_env([this](int i) { step_one(i); });
  return result_;
}

bool ThreadedVecEnv::supports_snapshots() const {
  return std::all_of(envs_.begin(), envs_.end(),
                     [](const auto& env) { return env->supports_snapshots(); });
}

void ThreadedVecEnv::save_state(SnapshotWriter& out, bool environments) const {
  out.section("ThreadedVecEnv");
  out.put(static_cast<int64_t>(num_envs()));
  const bool with_envs = environments && ready_ && supports_snapshots();
  out.put(with_envs);
  if (!with_envs) return;
  for (const auto& env : envs_) env->save_state(out);
}

bool ThreadedVecEnv::load_state(SnapshotReader& in) {
  in.section("ThreadedVecEnv");
  const int64_t count = in.get_int64();
  if (count != num_envs()) {
    throw Error("snapshot of " + std::to_string(count) + " environments, this vector env has " +
                    std::to_string(num_envs()),
                kWhere);
  }
  if (!in.get_bool()) return false;
  // Environments load one by one; a failure leaves the vector env needing a reset.
  ready_ = false;
  for (auto& env : envs_) env->load_state(in);
  ready_ = true;
  return true;
}

}  // namespace tendril::envs
