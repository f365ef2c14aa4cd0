#include "tendril/safety/filtered_vec_env.hpp"

#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::safety {

FilteredVecEnv::FilteredVecEnv(std::unique_ptr<envs::VecEnv> inner, const SafetyCritic& critic,
                               SafeActor safe_actor, double threshold)
    : VecEnvWrapper(std::move(inner)),
      critic_(critic),
      safe_actor_(std::move(safe_actor)),
      threshold_(threshold) {
  require(static_cast<bool>(safe_actor_), "the safe actor is empty", "FilteredVecEnv");
  require(inner_->normalizer() == nullptr,
          "the safety critic reads raw observations: filter below no VecNormalize",
          "FilteredVecEnv");
}

const envs::BatchMatrix& FilteredVecEnv::reset(std::optional<uint64_t> seed) {
  const envs::BatchMatrix& observations = inner_->reset(seed);
  observations_ = observations;
  return observations;
}

void FilteredVecEnv::save_state(SnapshotWriter& out, bool environments) const {
  out.section("safety filter");
  out.put(decisions_);
  out.put(interventions_);
  const bool with_observations = environments && observations_.rows() > 0;
  out.put(with_observations);
  if (with_observations) out.put_matrix(observations_);
  inner_->save_state(out, environments);
}

bool FilteredVecEnv::load_state(SnapshotReader& in) {
  in.section("safety filter");
  const int64_t decisions = in.get_int64();
  const int64_t interventions = in.get_int64();
  require(decisions >= 0 && interventions >= 0 && interventions <= decisions,
          "inconsistent decision counts", "FilteredVecEnv");
  envs::BatchMatrix observations;
  if (in.get_bool()) {
    observations.resize(num_envs(), observation_space().size());
    in.get_matrix(observations);
  }
  const bool restored = inner_->load_state(in);
  decisions_ = decisions;
  interventions_ = interventions;
  observations_ = restored ? std::move(observations) : envs::BatchMatrix();
  return restored;
}

const envs::VecStep& FilteredVecEnv::step(const envs::BatchMatrix& actions) {
  require(observations_.rows() == actions.rows() && observations_.rows() > 0,
          "a step needs a reset first (after construction or load_state) and one row per env",
          "FilteredVecEnv");
  executed_ = actions;
  intervened_.assign(static_cast<std::size_t>(actions.rows()), 0);
  for (Eigen::Index i = 0; i < actions.rows(); ++i) {
    const Observation x = observations_.row(i).transpose();
    const Action proposed = actions.row(i).transpose();
    ++decisions_;
    // Eq. (6.5): keep the proposal only where its safety value exceeds ε₂.
    if (critic_.value(x, proposed) > threshold_) continue;
    executed_.row(i) = safe_actor_(x).transpose();
    intervened_[static_cast<std::size_t>(i)] = 1;
    ++interventions_;
  }
  const envs::VecStep& step = inner_->step(executed_);
  observations_ = step.observations;
  return step;
}

}  // namespace tendril::safety
