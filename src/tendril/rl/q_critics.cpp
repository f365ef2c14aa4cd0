#include "tendril/rl/q_critics.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::rl {

QCritics::QCritics(int count, int64_t observation_size, int64_t action_size,
                   const std::vector<int64_t>& hidden, nn::Activation activation,
                   double learning_rate, Rng& init_rng) {
  std::vector<int64_t> sizes{observation_size + action_size};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(1);
  int64_t total = 0;
  for (int i = 0; i < count; ++i) {
    networks_.emplace_back(sizes, activation);
    offsets_.push_back(total);
    total += networks_.back().parameter_count();
  }
  parameters_.resize(total);
  for (int i = 0; i < count; ++i) {
    networks_[i].initialize(parameters_.segment(offsets_[i], networks_[i].parameter_count()),
                            init_rng);
  }
  target_ = parameters_;
  gradient_ = Eigen::VectorXf::Zero(total);
  optimizer_ = nn::Adam(total, {learning_rate});
  tapes_.resize(count);
  scratch_.resize(count);
}

void QCritics::forward(const Eigen::MatrixXf& inputs, bool target, int first) {
  const int used = first < 0 ? count() : std::min(first, count());
  values_.resize(used, inputs.cols());
  for (int i = 0; i < used; ++i) {
    networks_[i].forward(slice(target ? target_ : parameters_, i), inputs, tapes_[i]);
    values_.row(i) = tapes_[i].output();
  }
  last_forward_target_ = target;
}

void QCritics::backward(const Eigen::MatrixXf& value_gradient, bool parameters,
                        Eigen::MatrixXf* input_gradient) {
  require(!last_forward_target_, "no backward pass through the target critics", "rl::QCritics");
  require(value_gradient.rows() == values_.rows(),
          "one gradient row per critic of the forward pass", "rl::QCritics");
  for (int i = 0; i < static_cast<int>(values_.rows()); ++i) {
    Eigen::Ref<Eigen::VectorXf> gradient = parameters
                                               ? Eigen::Ref<Eigen::VectorXf>(gradient_.segment(
                                                     offsets_[i], networks_[i].parameter_count()))
                                               : Eigen::Ref<Eigen::VectorXf>(no_gradient_);
    Eigen::MatrixXf* inputs =
        input_gradient == nullptr ? nullptr : (i == 0 ? input_gradient : &input_gradient_);
    networks_[i].backward(slice(parameters_, i), tapes_[i], value_gradient.row(i), gradient, inputs,
                          scratch_[i]);
    if (input_gradient != nullptr && i > 0) *input_gradient += input_gradient_;
  }
}

void QCritics::step(double learning_rate, std::optional<double> max_grad_norm) {
  if (max_grad_norm) nn::clip_grad_norm(gradient_, *max_grad_norm);
  optimizer_.set_learning_rate(learning_rate);
  optimizer_.step(parameters_, gradient_);
  gradient_.setZero();
}

void QCritics::save(ArchiveWriter& writer, const std::string& prefix) const {
  writer.put_floats(prefix + "_parameters", parameters_);
  writer.put_floats(prefix + "_target", target_);
  save_adam(writer, prefix + "_adam", optimizer_);
}

std::function<void()> QCritics::prepare_load(const ArchiveReader& reader,
                                             const std::string& prefix) {
  Eigen::VectorXf parameters = reader.get_floats(prefix + "_parameters", parameters_.size());
  Eigen::VectorXf target = reader.get_floats(prefix + "_target", target_.size());
  std::function<void()> install_adam =
      prepare_adam(reader, prefix + "_adam", optimizer_, parameters_.size());
  return [this, parameters, target, install_adam] {
    parameters_ = parameters;
    target_ = target;
    install_adam();
  };
}

void QCritics::set_parameters(const Eigen::VectorXf& parameters) {
  require(parameters.size() == parameters_.size(),
          "critic parameters have " + std::to_string(parameters.size()) + " values, expected " +
              std::to_string(parameters_.size()),
          "rl::QCritics");
  parameters_ = parameters;
  target_ = parameters;
}

void concatenate_rows(const Eigen::Ref<const Eigen::MatrixXf>& top,
                      const Eigen::Ref<const Eigen::MatrixXf>& bottom, Eigen::MatrixXf& inputs) {
  inputs.resize(top.rows() + bottom.rows(), top.cols());
  inputs.topRows(top.rows()) = top;
  inputs.bottomRows(bottom.rows()) = bottom;
}

}  // namespace tendril::rl
