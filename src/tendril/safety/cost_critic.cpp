#include "tendril/safety/cost_critic.hpp"

#include <cstddef>
#include <memory>
#include <span>

#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"

namespace tendril::safety {

CostCriticSettings CostCriticSettings::from_config(const Config& config) {
  CostCriticSettings s;
  s.gamma = config.get_or("gamma", s.gamma);
  s.net_arch = config.get_or("net_arch", s.net_arch);
  s.learning_rate = config.get_or("learning_rate", s.learning_rate);
  s.tau = config.get_or("tau", s.tau);
  s.buffer_size = config.get_or("buffer_size", s.buffer_size);
  s.batch_size = config.get_or("batch_size", s.batch_size);
  s.learning_starts = config.get_or("learning_starts", s.learning_starts);
  s.gradient_steps = config.get_or("gradient_steps", s.gradient_steps);
  require(s.gamma > 0.0 && s.gamma < 1.0, "must lie in (0, 1)", config.where("gamma"));
  require(!s.net_arch.empty(), "needs at least one hidden layer", config.where("net_arch"));
  for (int64_t width : s.net_arch)
    require(width > 0, "widths must be positive", config.where("net_arch"));
  require(s.learning_rate > 0.0, "must be positive", config.where("learning_rate"));
  require(s.tau > 0.0 && s.tau <= 1.0, "must lie in (0, 1]", config.where("tau"));
  require(s.buffer_size >= 1 && s.batch_size >= 1, "must be at least 1",
          config.where("buffer_size/batch_size"));
  require(s.learning_starts >= 0 && s.gradient_steps >= 0, "must be non-negative",
          config.where("learning_starts/gradient_steps"));
  return s;
}

CostCritic::CostCritic(const rl::Policy& task_policy, const CostCriticSettings& settings,
                       uint64_t seed)
    : task_policy_(task_policy),
      settings_(settings),
      buffer_(settings.buffer_size, task_policy.observation_space().size(),
              task_policy.action_space().size()),
      rng_(seed) {
  require(task_policy.action_space().is_box(), "the cost critic needs a Box action space",
          "CostCritic");
  Rng init_rng(seed, 1);
  critics_ =
      rl::QCritics(2, task_policy.observation_space().size(), task_policy.action_space().size(),
                   settings.net_arch, nn::Activation::kRelu, settings.learning_rate, init_rng);
}

void CostCritic::on_step(const rl::StepEvent& event) {
  const Space& space = task_policy_.action_space();
  for (Eigen::Index i = 0; i < event.observations.rows(); ++i) {
    const std::optional<double> cost =
        event.step.infos[static_cast<std::size_t>(i)].get(info_keys::kCost);
    require(cost.has_value(), "the environment reports no \"cost\" info", "CostCritic");
    const bool violation = *cost > 0.0;
    Eigen::MatrixXf action = event.actions.row(i).transpose();
    rl::unscale_from_bounds(space, action);
    buffer_.add(event.observations.row(i).transpose(), action.col(0), violation ? 1.0f : 0.0f,
                event.step.final_observations.row(i).transpose(),
                violation || event.step.terminated[static_cast<std::size_t>(i)] != 0);
  }
  if (buffer_.size() >= settings_.learning_starts) {
    for (int64_t k = 0; k < settings_.gradient_steps; ++k) train();
  }
}

void CostCritic::train() {
  const int64_t batch_size = settings_.batch_size;
  buffer_.sample(batch_size, rng_, batch_);
  // a' ~ π(·|s'), in [−1, 1].
  next_observation_rows_ = batch_.next_observations.transpose();
  task_policy_.act(next_observation_rows_, /*deterministic=*/false, rng_, next_action_rows_);
  next_actions_ = next_action_rows_.transpose();
  rl::unscale_from_bounds(task_policy_.action_space(), next_actions_);
  rl::concatenate_rows(batch_.next_observations, next_actions_, inputs_);
  critics_.forward(inputs_, /*target=*/true);
  // y = c' + (1 − d) γ_risk max_i Q̄_i(s', a'); d = 1 at a violation (c' = 1) or a termination.
  const Eigen::VectorXf next = critics_.values().colwise().maxCoeff().transpose();
  const auto gamma = static_cast<float>(settings_.gamma);
  const Eigen::VectorXf targets =
      (batch_.rewards.array() + gamma * (1.0f - batch_.terminated.array()) * next.array()).matrix();
  // Step on ½ Σ_i mean (Q_i(s, a) − y)².
  rl::concatenate_rows(batch_.observations, batch_.actions, inputs_);
  critics_.forward(inputs_, /*target=*/false);
  value_gradient_ =
      (critics_.values().rowwise() - targets.transpose()) / static_cast<float>(batch_size);
  last_loss_ = 0.5 * static_cast<double>(value_gradient_.squaredNorm()) * batch_size;
  critics_.backward(value_gradient_, /*parameters=*/true, nullptr);
  critics_.step(settings_.learning_rate);
  critics_.update_target(settings_.tau);
  ++updates_;
}

const Eigen::VectorXf& CostCritic::values(const Eigen::MatrixXf& observations,
                                          const Eigen::MatrixXf& actions) {
  rl::concatenate_rows(observations, actions, inputs_);
  critics_.forward(inputs_, /*target=*/false);
  const Eigen::MatrixXf& q = critics_.values();
  values_.resize(q.cols());
  larger_.resize(static_cast<std::size_t>(q.cols()));
  for (Eigen::Index j = 0; j < q.cols(); ++j) {
    values_[j] = q.col(j).maxCoeff(&larger_[static_cast<std::size_t>(j)]);
  }
  return values_;
}

void CostCritic::add_action_gradient(float weight, Eigen::Ref<Eigen::MatrixXf> action_gradient) {
  const Eigen::MatrixXf& q = critics_.values();
  value_gradient_.setZero(q.rows(), q.cols());
  for (Eigen::Index j = 0; j < q.cols(); ++j) {
    value_gradient_(larger_[static_cast<std::size_t>(j)], j) = weight;
  }
  critics_.backward(value_gradient_, /*parameters=*/false, &input_gradient_);
  action_gradient += input_gradient_.bottomRows(action_gradient.rows());
}

void CostCritic::save(ArchiveWriter& writer, const std::string& prefix) const {
  critics_.save(writer, prefix + "critics");
  const std::string buffer = buffer_.serialize();
  writer.put_bytes(prefix + "buffer", std::as_bytes(std::span<const char>(buffer)));
  writer.put_rng(prefix + "rng", rng_);
  writer.put(prefix + "updates", updates_);
  writer.put(prefix + "last_loss", last_loss_);
}

std::function<void()> CostCritic::prepare_load(const ArchiveReader& reader,
                                               const std::string& prefix) {
  std::function<void()> install_critics = critics_.prepare_load(reader, prefix + "critics");
  const Snapshot bytes = reader.get_bytes(prefix + "buffer");
  auto buffer = std::make_shared<rl::ReplayBuffer>(buffer_.capacity(), buffer_.observation_size(),
                                                   buffer_.action_size());
  buffer->load_bytes(std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                     reader.name() + " (" + prefix + "buffer)");
  const Rng rng = reader.get_rng(prefix + "rng");
  const int64_t updates = reader.get_int(prefix + "updates");
  require(updates >= 0, "a negative update count", reader.name());
  const double last_loss = reader.get_double(prefix + "last_loss");
  return [this, install_critics, buffer, rng, updates, last_loss] {
    install_critics();
    buffer_ = std::move(*buffer);
    rng_ = rng;
    updates_ = updates;
    last_loss_ = last_loss;
  };
}

}  // namespace tendril::safety
