#include "tendril/dynamics/policy_heads.hpp"

#include "tendril/dynamics/learned_model_head.hpp"
#include "tendril/dynamics/model_file.hpp"
#include "tendril/dynamics/model_file_format.hpp"

namespace tendril::dynamics {

void install_policy_heads() {
  auto kind = [](LearnedModelHead::Part part) {
    nn::FeatureHeadKind builder;
    builder.create = [part](const nn::FeatureHeadSpec& spec, Rng& rng) -> nn::CreatedHead {
      std::unique_ptr<Model> model = load_model(spec.model);
      auto head = std::make_shared<LearnedModelHead>(model->description(), part);
      if (!spec.pretrained) model->network().initialize(rng);
      Eigen::VectorXf weights = head->weights_of(model->network());
      return {std::move(head), std::move(weights)};
    };
    builder.read = [part](const ArchiveReader& reader,
                          const std::string& prefix) -> std::shared_ptr<const nn::FeatureHead> {
      return std::make_shared<LearnedModelHead>(
          parse_description_yaml(reader.get_string(prefix + "_model"), reader.name()), part);
    };
    return builder;
  };
  nn::install_feature_head_kind(LearnedModelHead::kEncoderKind,
                                kind(LearnedModelHead::Part::kEncoder));
  nn::install_feature_head_kind(LearnedModelHead::kFullKind, kind(LearnedModelHead::Part::kFull));
}

}  // namespace tendril::dynamics
