#include "tendril/rl/observation_encoder.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::rl {

ObservationEncoder::ObservationEncoder(std::shared_ptr<const nn::FeatureHead> head,
                                       int64_t observation_size)
    : head_(std::move(head)), observation_size_(observation_size) {
  if (head_) {
    require(head_->input_size() <= observation_size_,
            "the '" + head_->kind() + "' head reads " + std::to_string(head_->input_size()) +
                " values, but an observation has only " + std::to_string(observation_size_) +
                " (does the environment append its history, e.g. env.params.history?)",
            "policy head");
  }
}

void ObservationEncoder::encode(const Eigen::Ref<const Eigen::VectorXf>& parameters,
                                const Eigen::Ref<const Eigen::MatrixXf>& observations, bool record,
                                Pass& pass) const {
  require(observations.rows() == observation_size_,
          "observations have " + std::to_string(observations.rows()) + " values, expected " +
              std::to_string(observation_size_),
          "rl::ObservationEncoder");
  if (!head_) {
    pass.encoded = observations;
    return;
  }
  if (!pass.head) pass.head = head_->make_tape();
  const int64_t direct = direct_size(), features = feature_size();
  head_->forward(parameters, observations.bottomRows(head_->input_size()), record, *pass.head);
  norm_.forward(pass.head->output, pass.norm);
  pass.encoded.resize(encoded_size(), observations.cols());
  pass.encoded.topRows(features) = pass.norm.output;
  pass.encoded.bottomRows(direct) = observations.topRows(direct);
}

void ObservationEncoder::backward(const Eigen::Ref<const Eigen::VectorXf>& parameters, Pass& pass,
                                  const Eigen::Ref<const Eigen::MatrixXf>& encoded_gradient,
                                  Eigen::Ref<Eigen::VectorXf> parameter_gradient) const {
  require(head_ != nullptr && pass.head != nullptr, "no head pass to differentiate",
          "rl::ObservationEncoder");
  norm_.backward(pass.norm, encoded_gradient.topRows(feature_size()), pass.norm_gradient);
  head_->backward(parameters, *pass.head, pass.norm_gradient, parameter_gradient);
}

}  // namespace tendril::rl
