#include "tendril/rl/policy.hpp"

#include <functional>
#include <map>

#include "tendril/core/error.hpp"
#include "tendril/nn/mlp_archive.hpp"
#include "tendril/rl/actor_critic_policy.hpp"
#include "tendril/rl/dqn/q_greedy_policy.hpp"
#include "tendril/rl/sac/squashed_gaussian_policy.hpp"
#include "tendril/rl/td3/deterministic_policy.hpp"

namespace tendril::rl {

namespace {

constexpr int64_t kPolicyFormat = 1;

using Reader =
    std::function<std::unique_ptr<Policy>(const ArchiveReader&, const Space&, const Space&)>;

// Every kind of policy a model file can hold.
const std::map<std::string, Reader>& policy_readers() {
  static const std::map<std::string, Reader> readers{
      {"actor_critic", &ActorCriticPolicy::read},
      {"squashed_gaussian", &SquashedGaussianPolicy::read},
      {"deterministic", &DeterministicPolicy::read},
      {"q_greedy", &QGreedyPolicy::read},
  };
  return readers;
}

}  // namespace

Policy::Policy(Space observation_space, Space action_space)
    : observation_space_(std::move(observation_space)), action_space_(std::move(action_space)) {
  require(observation_space_.is_box(),
          "policies act on Box observations, not " + observation_space_.describe(), "rl::Policy");
}

void Policy::act(const envs::BatchMatrix& observations, bool deterministic, Rng& rng,
                 envs::BatchMatrix& actions) const {
  const int size = observation_space_.size();
  if (observations.cols() != size) {
    throw Error("observations have " + std::to_string(observations.cols()) +
                    " components, the policy expects " + std::to_string(size),
                "rl::Policy::act");
  }
  if (!observations.allFinite()) {
    throw Error("an observation is not finite", "rl::Policy::act");
  }
  columns_ = observations.transpose();
  if (normalization_) {
    for (Eigen::Index i = 0; i < columns_.cols(); ++i) {
      columns_.col(i) = normalization_->statistics
                            .normalize(columns_.col(i).cast<double>(), normalization_->epsilon,
                                       normalization_->clip)
                            .cast<float>();
    }
  }
  act_columns(columns_, deterministic, rng, action_columns_);
  actions = action_columns_.transpose();
}

Action Policy::act(const Observation& observation, bool deterministic, Rng& rng) const {
  envs::BatchMatrix batch = observation.transpose();
  envs::BatchMatrix actions;
  act(batch, deterministic, rng, actions);
  return actions.row(0).transpose();
}

ArchiveWriter Policy::archive(const std::optional<ObservationNormalization>& normalization) const {
  ArchiveWriter writer("policy");
  writer.put("format", kPolicyFormat);
  writer.put("kind", kind());
  write_space(writer, "observation_space", observation_space_);
  write_space(writer, "action_space", action_space_);
  if (normalization) {
    writer.put_doubles("normalization_statistics", normalization->statistics.to_array());
    writer.put("normalization_clip", normalization->clip);
    writer.put("normalization_epsilon", normalization->epsilon);
  }
  write(writer);
  return writer;
}

void Policy::save(const std::filesystem::path& file,
                  const std::optional<ObservationNormalization>& normalization) const {
  archive(normalization).commit(file);
}

std::string Policy::serialize() const { return archive(normalization_).serialize(); }

namespace {

std::unique_ptr<Policy> read_policy(const ArchiveReader& reader) {
  const int64_t format = reader.get_int("format");
  if (format != kPolicyFormat) {
    throw Error("policy format " + std::to_string(format) + " is not supported (this build reads " +
                    std::to_string(kPolicyFormat) + ")",
                reader.name());
  }
  const std::string kind = reader.get_string("kind");
  const auto found = policy_readers().find(kind);
  if (found == policy_readers().end()) {
    throw Error("unknown policy kind '" + kind + "'", reader.name());
  }
  const Space observation_space = read_space(reader, "observation_space");
  const Space action_space = read_space(reader, "action_space");
  std::unique_ptr<Policy> policy;
  try {
    policy = found->second(reader, observation_space, action_space);
    if (reader.contains("normalization_statistics")) {
      policy->set_observation_normalization(ObservationNormalization{
          envs::RunningMeanStd::from_array(reader.get_doubles("normalization_statistics"),
                                           observation_space.size()),
          reader.get_double("normalization_clip"), reader.get_double("normalization_epsilon")});
    }
  } catch (const Error& e) {
    if (e.where() == reader.name()) throw;
    throw Error(e.what(), reader.name());
  }
  return policy;
}

}  // namespace

std::unique_ptr<Policy> load_policy(const std::filesystem::path& file) {
  return read_policy(ArchiveReader(file, "policy"));
}

std::unique_ptr<Policy> load_policy_bytes(std::string bytes, const std::string& name) {
  return read_policy(ArchiveReader::from_bytes(std::move(bytes), "policy", name));
}

void write_mlp(ArchiveWriter& writer, const std::string& prefix, const nn::DenseMlp& mlp) {
  nn::write_dense_mlp(writer, prefix, mlp);
}

nn::DenseMlp read_mlp(const ArchiveReader& reader, const std::string& prefix) {
  return nn::read_dense_mlp(reader, prefix);
}

void write_space(ArchiveWriter& writer, const std::string& prefix, const Space& space) {
  writer.put(prefix + "_discrete", int64_t{space.is_discrete()});
  if (space.is_discrete()) {
    writer.put(prefix + "_n", space.n());
  } else {
    writer.put_floats(prefix + "_low", space.low());
    writer.put_floats(prefix + "_high", space.high());
  }
}

Space read_space(const ArchiveReader& reader, const std::string& prefix) {
  try {
    if (reader.get_int(prefix + "_discrete") != 0)
      return Space::discrete(reader.get_int(prefix + "_n"));
    return Space::box(reader.get_floats(prefix + "_low"), reader.get_floats(prefix + "_high"));
  } catch (const Error& e) {
    if (e.where() == reader.name()) throw;
    throw Error(prefix + ": " + e.what_wrong(), reader.name());
  }
}

void scale_to_bounds(const Space& space, Eigen::MatrixXf& actions) {
  if (!space.is_box()) return;
  const Eigen::ArrayXf half_range = 0.5f * (space.high() - space.low()).array();
  for (Eigen::Index i = 0; i < actions.cols(); ++i) {
    const Eigen::ArrayXf scaled = actions.col(i).array().cwiseMax(-1.0f).cwiseMin(1.0f);
    actions.col(i) = (space.low().array() + (scaled + 1.0f) * half_range).matrix();
  }
}

void unscale_from_bounds(const Space& space, Eigen::MatrixXf& actions) {
  if (!space.is_box()) return;
  const Eigen::ArrayXf low = space.low().array(), range = (space.high() - space.low()).array();
  for (Eigen::Index i = 0; i < actions.cols(); ++i) {
    actions.col(i) = (2.0f * (actions.col(i).array() - low) / range - 1.0f)
                         .cwiseMax(-1.0f)
                         .cwiseMin(1.0f)
                         .matrix();
  }
}

void clip_to_bounds(const Space& space, Eigen::MatrixXf& actions) {
  if (!space.is_box()) return;
  for (Eigen::Index i = 0; i < actions.cols(); ++i) {
    actions.col(i) = actions.col(i).cwiseMax(space.low()).cwiseMin(space.high());
  }
}

}  // namespace tendril::rl
