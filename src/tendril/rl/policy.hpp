#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "tendril/core/archive.hpp"
#include "tendril/core/env.hpp"
#include "tendril/core/policy.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/vector/vec_step.hpp"
#include "tendril/envs/wrappers/running_mean_std.hpp"
#include "tendril/nn/dense_mlp.hpp"

namespace tendril::rl {

// Frozen observation statistics a policy applies before its network: those of the VecNormalize
// it was trained behind, so that the deployed policy acts on the environment's raw
// observations (SB3 keeps them in a separate VecNormalize file; here they travel with the
// policy). obs' = clip((obs − mean) / sqrt(var + ε), ±clip).
struct ObservationNormalization {
  envs::RunningMeanStd statistics;
  double clip = 10.0;
  double epsilon = 1e-8;
};

// What acts: observations in, actions out, apart from the algorithm that trained it and from
// any environment pool (DESIGN.md, "The seams"). Evaluation, recording, safety filters,
// adaptation, Python and hardware loops use policies. An algorithm's policy is the very object
// it trains (its weights are the trained weights, no copy); `save` writes a model file that
// `load_policy` turns back into a policy that acts identically. No LibTorch.
//
// A policy keeps scratch buffers: one policy must not act from two threads at once.
class Policy : public tendril::Policy {
 public:
  const Space& observation_space() const override { return observation_space_; }
  const Space& action_space() const override { return action_space_; }
  // "actor_critic", "squashed_gaussian", "deterministic", "q_greedy".
  virtual std::string kind() const = 0;

  // One row per observation in, one row per action out, in the action space's units and
  // bounds (a Discrete action is its index). `deterministic` takes the distribution's mode;
  // otherwise draws come from `rng`. Raises Error on a wrong observation size or a non-finite
  // observation.
  void act(const BatchMatrix& observations, bool deterministic, Rng& rng,
           BatchMatrix& actions) const override;
  Action act(const Observation& observation, bool deterministic, Rng& rng) const override;

  // Normalization applied to observations before the network (none by default).
  void set_observation_normalization(std::optional<ObservationNormalization> normalization) {
    normalization_ = std::move(normalization);
  }
  const std::optional<ObservationNormalization>& observation_normalization() const {
    return normalization_;
  }

  // Writes the model file (an archive of kind "policy", checksummed, atomic), with this
  // policy's observation normalization or the one given.
  void save(const std::filesystem::path& file) const { save(file, normalization_); }
  void save(const std::filesystem::path& file,
            const std::optional<ObservationNormalization>& normalization) const;
  // The model file's bytes (what `save` writes), for files that embed a policy.
  std::string serialize() const;

 protected:
  Policy(Space observation_space, Space action_space);

  // The network's actions for `observations` (observation_size × batch, already normalized)
  // into `actions` (action components × batch, env units; indices for Discrete).
  virtual void act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                           bool deterministic, Rng& rng, Eigen::MatrixXf& actions) const = 0;
  // The kind's own entries of the model file.
  virtual void write(ArchiveWriter& writer) const = 0;

 private:
  ArchiveWriter archive(const std::optional<ObservationNormalization>& normalization) const;

  Space observation_space_, action_space_;
  std::optional<ObservationNormalization> normalization_;
  mutable Eigen::MatrixXf columns_, action_columns_;
};

// Reads a model file written by Policy::save. Raises Error naming the file on anything that is
// not an intact policy file of a known kind.
std::unique_ptr<Policy> load_policy(const std::filesystem::path& file);
// The same for a model file's bytes (Policy::serialize); `name` stands for the file in messages.
std::unique_ptr<Policy> load_policy_bytes(std::string bytes, const std::string& name);

// A DenseMlp's shape (sizes, hidden activation, tanh output) in and out of archives.
void write_mlp(ArchiveWriter& writer, const std::string& prefix, const nn::DenseMlp& mlp);
nn::DenseMlp read_mlp(const ArchiveReader& reader, const std::string& prefix);

// Spaces in and out of archives (policy files, checkpoints), under `prefix`.
void write_space(ArchiveWriter& writer, const std::string& prefix, const Space& space);
Space read_space(const ArchiveReader& reader, const std::string& prefix);

// Maps actions in [−1, 1] affinely onto a Box's finite bounds (SB3's unscale_action, after
// clipping to [−1, 1]); off-policy actors act in [−1, 1].
void scale_to_bounds(const Space& space, Eigen::MatrixXf& actions);
// The inverse: a Box's actions (env units, columns) into [−1, 1], clipped there; what an
// off-policy algorithm stores for actions executed by someone else.
void unscale_from_bounds(const Space& space, Eigen::MatrixXf& actions);
// Clips actions to a Box's bounds (what SB3 does to on-policy Gaussian samples).
void clip_to_bounds(const Space& space, Eigen::MatrixXf& actions);

}  // namespace tendril::rl
