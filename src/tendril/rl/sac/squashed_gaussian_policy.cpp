#include "tendril/rl/sac/squashed_gaussian_policy.hpp"

#include "tendril/core/error.hpp"
#include "tendril/nn/feature_heads.hpp"

namespace tendril::rl {

namespace {

nn::DenseMlp actor(int64_t input_size, const Space& action_space,
                   const std::vector<int64_t>& hidden, nn::Activation activation, bool use_sde) {
  require(action_space.is_box(),
          "a squashed Gaussian needs a Box action space, not " + action_space.describe(),
          "rl::SquashedGaussianPolicy");
  std::vector<int64_t> sizes{input_size};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(use_sde ? action_space.size() : 2 * action_space.size());
  return nn::DenseMlp(sizes, activation);
}

}  // namespace

SquashedGaussianPolicy::SquashedGaussianPolicy(const Space& observation_space,
                                               const Space& action_space,
                                               const std::vector<int64_t>& hidden,
                                               nn::Activation activation, bool use_sde,
                                               std::shared_ptr<const nn::FeatureHead> head)
    : SquashedGaussianPolicy(
          observation_space, action_space,
          actor(ObservationEncoder(head, observation_space.size()).encoded_size(), action_space,
                hidden, activation, use_sde),
          use_sde, head) {}

SquashedGaussianPolicy::SquashedGaussianPolicy(const Space& observation_space,
                                               const Space& action_space, nn::DenseMlp network,
                                               bool use_sde,
                                               std::shared_ptr<const nn::FeatureHead> head)
    : Policy(observation_space, action_space),
      encoder_(std::move(head), observation_space.size()),
      head_parameters_(
          Eigen::VectorXf::Zero(encoder_.has_head() ? encoder_.head().parameter_count() : 0)),
      network_(std::move(network)),
      use_sde_(use_sde),
      latent_size_(network_.sizes().size() > 2 ? network_.sizes()[network_.sizes().size() - 2]
                                               : network_.input_size()) {
  const int64_t actions = action_space.size();
  require(network_.input_size() == encoder_.encoded_size() &&
              network_.output_size() == (use_sde ? actions : 2 * actions) &&
              !network_.tanh_output(),
          "the actor does not fit the spaces", "rl::SquashedGaussianPolicy");
  parameters_ =
      Eigen::VectorXf::Zero(network_.parameter_count() + (use_sde ? latent_size_ * actions : 0));
}

Eigen::Map<const Eigen::MatrixXf> SquashedGaussianPolicy::log_std() const {
  return {parameters_.data() + network_.parameter_count(), latent_size_, action_space().size()};
}

const Eigen::MatrixXf& SquashedGaussianPolicy::latent_of(const nn::DenseMlp::Tape& tape) const {
  return tape.outputs.size() >= 2 ? tape.outputs[tape.outputs.size() - 2] : tape.input;
}

Eigen::MatrixXf SquashedGaussianPolicy::standard_normal_matrix(Rng& rng) const {
  Eigen::MatrixXf matrix(latent_size_, action_space().size());
  for (Eigen::Index i = 0; i < matrix.size(); ++i) {
    matrix.data()[i] = static_cast<float>(rng.normal());
  }
  return matrix;
}

void SquashedGaussianPolicy::sample(const Eigen::Ref<const Eigen::MatrixXf>& inputs, Rng& rng,
                                    const Eigen::MatrixXf& exploration, Sample& sample) const {
  network_.forward(parameters_.head(network_.parameter_count()), inputs, sample.tape);
  if (use_sde_) {
    sample.sde.standard_normal = exploration;
    sample.sde.evaluate(sample.tape.output(), latent_of(sample.tape), log_std());
    return;
  }
  Eigen::MatrixXf& noise = sample.gaussian.noise;
  noise.resize(action_space().size(), inputs.cols());
  for (Eigen::Index i = 0; i < noise.size(); ++i) {
    noise.data()[i] = static_cast<float>(rng.normal());
  }
  sample.gaussian.evaluate(sample.tape.output());
}

void SquashedGaussianPolicy::act_columns(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                                         bool deterministic, Rng& rng,
                                         Eigen::MatrixXf& actions) const {
  if (encoder_.has_head()) encoder_.encode(head_parameters_, observations, false, pass_);
  const Eigen::Ref<const Eigen::MatrixXf> inputs =
      encoder_.has_head() ? Eigen::Ref<const Eigen::MatrixXf>(pass_.encoded) : observations;
  if (deterministic) {
    network_.forward(parameters_.head(network_.parameter_count()), inputs, sample_.tape);
    actions = sample_.tape.output().topRows(action_space().size());
    // gSDE's mean is clipped to ±2 (SB3's clip_mean) before the squash.
    if (use_sde_) actions = actions.cwiseMax(-2.0f).cwiseMin(2.0f);
    actions = actions.array().tanh().matrix();
  } else {
    sample(inputs, rng, use_sde_ ? standard_normal_matrix(rng) : no_exploration_, sample_);
    actions = actions_of(sample_);
  }
  scale_to_bounds(action_space(), actions);
}

void SquashedGaussianPolicy::write(ArchiveWriter& writer) const {
  write_mlp(writer, "actor", network_);
  writer.put("use_sde", int64_t{use_sde_});
  writer.put_floats("parameters", parameters_);
  if (encoder_.has_head()) {
    nn::write_feature_head(writer, "head", encoder_.head());
    writer.put_floats("head_parameters", head_parameters_);
  }
}

std::unique_ptr<Policy> SquashedGaussianPolicy::read(const ArchiveReader& reader,
                                                     const Space& observation_space,
                                                     const Space& action_space) {
  std::shared_ptr<const nn::FeatureHead> head;
  if (reader.contains("head_kind")) head = nn::read_feature_head(reader, "head");
  std::unique_ptr<SquashedGaussianPolicy> policy(
      new SquashedGaussianPolicy(observation_space, action_space, read_mlp(reader, "actor"),
                                 reader.get_int("use_sde") != 0, std::move(head)));
  policy->parameters_ = reader.get_floats("parameters", policy->parameters_.size());
  if (policy->encoder_.has_head()) {
    policy->head_parameters_ =
        reader.get_floats("head_parameters", policy->head_parameters_.size());
  }
  return policy;
}

}  // namespace tendril::rl
