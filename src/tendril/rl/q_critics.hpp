#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "tendril/core/archive.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/nn/gradient.hpp"
#include "tendril/rl/adam_checkpoint.hpp"

namespace tendril::rl {

// The state-action critics of SAC, TD3 and DDPG: `count` networks Q_i(s, a) over the
// concatenated input [s; a], all their parameters in one vector with one Adam optimizer (SB3's
// ContinuousCritic), and a Polyak-averaged target copy.
class QCritics {
 public:
  QCritics() = default;
  QCritics(int count, int64_t observation_size, int64_t action_size,
           const std::vector<int64_t>& hidden, nn::Activation activation, double learning_rate,
           Rng& init_rng);

  int count() const { return static_cast<int>(networks_.size()); }

  // Q_i of each column of `inputs` ((observation + action) × batch) with the online or the
  // target parameters, as rows of `values()` (count × batch) — of the first `first` critics
  // only when given (TD3's actor needs Q_1 alone).
  void forward(const Eigen::MatrixXf& inputs, bool target, int first = -1);
  const Eigen::MatrixXf& values() const { return values_; }

  // Back-propagates ∂L/∂Q (one row per critic of the last `forward`) through it: adds
  // ∂L/∂parameters to `gradient()` when `parameters` is true, and writes Σ_i ∂L/∂inputs to
  // `input_gradient` when given (for the actor's update through the critics).
  void backward(const Eigen::MatrixXf& value_gradient, bool parameters,
                Eigen::MatrixXf* input_gradient);

  // One Adam step from `gradient()`, which is then zeroed; with `max_grad_norm`, the gradient of
  // all critics together is first clipped to that L2 norm (nn::clip_grad_norm).
  void step(double learning_rate, std::optional<double> max_grad_norm = std::nullopt);
  // target ← (1 − τ) target + τ online.
  void update_target(double tau) { nn::polyak_update(target_, parameters_, tau); }

  void save(ArchiveWriter& writer, const std::string& prefix) const;
  // Returns the action that installs the read state.
  std::function<void()> prepare_load(const ArchiveReader& reader, const std::string& prefix);

  const Eigen::VectorXf& parameters() const { return parameters_; }
  // Sets the online and target parameters (a model file's critics); raises Error on a wrong size.
  void set_parameters(const Eigen::VectorXf& parameters);
  const nn::DenseMlp& network(int i) const { return networks_.at(static_cast<std::size_t>(i)); }

 private:
  Eigen::Ref<const Eigen::VectorXf> slice(const Eigen::VectorXf& all, int i) const {
    return all.segment(offsets_[i], networks_[i].parameter_count());
  }

  std::vector<nn::DenseMlp> networks_;
  std::vector<int64_t> offsets_;
  Eigen::VectorXf parameters_, target_, gradient_, no_gradient_;
  nn::Adam optimizer_;
  std::vector<nn::DenseMlp::Tape> tapes_;
  std::vector<std::vector<Eigen::MatrixXf>> scratch_;
  Eigen::MatrixXf values_, input_gradient_;
  bool last_forward_target_ = false;
};

// [observations; actions] column by column into `inputs` (resized as needed).
void concatenate_rows(const Eigen::Ref<const Eigen::MatrixXf>& top,
                      const Eigen::Ref<const Eigen::MatrixXf>& bottom, Eigen::MatrixXf& inputs);

}  // namespace tendril::rl
