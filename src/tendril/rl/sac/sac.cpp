#include "tendril/rl/sac/sac.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::rl {

namespace {

constexpr uint64_t kInitStream = 100;

std::vector<int64_t> actor_sizes(int64_t observation_size, const std::vector<int64_t>& hidden,
                                 int64_t head_size) {
  std::vector<int64_t> sizes{observation_size};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(head_size);
  return sizes;
}

}  // namespace

Sac::Sac(envs::VecEnv& env, const SacConfig& config, uint64_t seed)
    : OffPolicyAlgorithm("SAC", env, config.common, seed), config_(config) {
  config_.validate();
  require(env.action_space().is_box(),
          "SAC needs a Box action space, not " + env.action_space().describe(), "SAC");
  const int64_t observations = observation_size();
  const int64_t actions = action_size();
  target_entropy_ = config_.target_entropy.value_or(-static_cast<double>(actions));
  Rng init_rng(seed, kInitStream);
  const std::vector<int64_t>& hidden = config_.common.net_arch;
  actor_ = nn::DenseMlp(actor_sizes(observations, hidden, config_.use_sde ? actions : 2 * actions),
                        config_.common.activation);
  latent_size_ = hidden.empty() ? observations : hidden.back();
  const int64_t log_std_count = config_.use_sde ? latent_size_ * actions : 0;
  const int64_t count = actor_.parameter_count() + log_std_count;
  actor_parameters_.resize(count);
  actor_.initialize(actor_parameters_.head(actor_.parameter_count()), init_rng);
  actor_parameters_.tail(log_std_count).setConstant(static_cast<float>(config_.log_std_init));
  actor_gradient_ = Eigen::VectorXf::Zero(count);
  const double learning_rate = config_.common.learning_rate.initial;
  actor_optimizer_ = nn::Adam(count, {learning_rate});
  env_exploration_.resize(num_envs());
  critics_ = QCritics(2, observations, actions, config_.common.critic_arch(),
                      config_.common.activation, learning_rate, init_rng);
  log_ent_coef_ = Eigen::VectorXf::Constant(1, static_cast<float>(std::log(config_.ent_coef)));
  ent_coef_optimizer_ = nn::Adam(1, {learning_rate});
}

double Sac::entropy_coefficient() const { return std::exp(static_cast<double>(log_ent_coef_[0])); }

const Eigen::MatrixXf& Sac::latent_of(const nn::DenseMlp::Tape& tape) const {
  return tape.outputs.size() >= 2 ? tape.outputs[tape.outputs.size() - 2] : tape.input;
}

Eigen::Map<const Eigen::MatrixXf> Sac::log_std() const {
  return {actor_parameters_.data() + actor_.parameter_count(), latent_size_, action_size()};
}

Eigen::MatrixXf Sac::standard_normal_matrix(Rng& rng) const {
  Eigen::MatrixXf matrix(latent_size_, action_size());
  for (Eigen::Index i = 0; i < matrix.size(); ++i)
    matrix.data()[i] = static_cast<float>(rng.normal());
  return matrix;
}

void Sac::sample_policy(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                        const Eigen::MatrixXf& exploration, PolicySample& sample) const {
  actor_.forward(actor_parameters_.head(actor_.parameter_count()), observations, sample.tape);
  if (config_.use_sde) {
    sample.sde.standard_normal = exploration;
    sample.sde.evaluate(sample.tape.output(), latent_of(sample.tape), log_std());
    return;
  }
  Eigen::MatrixXf& noise = sample.gaussian.noise;
  noise.resize(action_size(), observations.cols());
  for (Eigen::Index i = 0; i < noise.size(); ++i)
    noise.data()[i] = static_cast<float>(rng.normal());
  sample.gaussian.evaluate(sample.tape.output());
}

void Sac::act(const Eigen::Ref<const Eigen::MatrixXf>& observations, ActMode mode, Rng& rng,
              Eigen::MatrixXf& actions) {
  if (mode == ActMode::kDeterministic) {
    actor_.forward(actor_parameters_.head(actor_.parameter_count()), observations, act_tape_);
    actions = act_tape_.output().topRows(action_size());
    // gSDE's mean is clipped to ±2 (SB3's clip_mean) before the squash.
    if (config_.use_sde) actions = actions.cwiseMax(-2.0f).cwiseMin(2.0f);
    actions = actions.array().tanh().matrix();
    return;
  }
  PolicySample sample;
  if (!config_.use_sde) {
    sample_policy(observations, rng, exploration_, sample);
    actions = sample.gaussian.actions;
    return;
  }
  if (mode == ActMode::kStochastic) {
    sample_policy(observations, rng, standard_normal_matrix(rng), sample);
    actions = sample.sde.actions;
    return;
  }
  // Collecting: each env keeps its exploration matrix until the next collection starts, or for
  // `sde_sample_freq` steps (SB3's reset_noise).
  if (resample_exploration_ ||
      (config_.sde_sample_freq > 0 && steps_since_resample_ >= config_.sde_sample_freq)) {
    for (auto& matrix : env_exploration_) matrix = standard_normal_matrix(rng);
    resample_exploration_ = false;
    steps_since_resample_ = 0;
  }
  ++steps_since_resample_;
  actions.resize(action_size(), observations.cols());
  for (Eigen::Index i = 0; i < observations.cols(); ++i) {
    sample_policy(observations.col(i), rng, env_exploration_[i], sample);
    actions.col(i) = sample.sde.actions;
  }
}

TrainStats Sac::train(int64_t gradient_steps, double progress_remaining) {
  const double learning_rate = config_.common.learning_rate.at(progress_remaining);
  const int64_t batch_size = config_.common.batch_size;
  const auto inverse_batch = 1.0f / static_cast<float>(batch_size);
  const auto gamma = static_cast<float>(config_.common.gamma);
  const int64_t a = action_size();
  double actor_loss_sum = 0.0, critic_loss_sum = 0.0, ent_coef_sum = 0.0, ent_loss_sum = 0.0;

  for (int64_t step = 0; step < gradient_steps; ++step) {
    buffer().sample(batch_size, sample_rng(), batch_);
    // gSDE: one exploration matrix for the whole batch, new at every gradient step (SB3).
    if (config_.use_sde) exploration_ = standard_normal_matrix(sample_rng());
    sample_policy(batch_.observations, sample_rng(), exploration_, current_);

    // α: minimise −log α · (log π + H̄) (eq. 18), with α taken before its own step, as SB3.
    const auto ent_coef = static_cast<float>(entropy_coefficient());
    if (config_.auto_entropy) {
      const double mean_term =
          (log_probs_of(current_).array() + static_cast<float>(target_entropy_))
              .cast<double>()
              .mean();
      ent_loss_sum += -static_cast<double>(log_ent_coef_[0]) * mean_term;
      ent_coef_optimizer_.set_learning_rate(learning_rate);
      ent_coef_optimizer_.step(log_ent_coef_,
                               Eigen::VectorXf::Constant(1, static_cast<float>(-mean_term)));
    }
    ent_coef_sum += ent_coef;

    // Critic targets: y = r + γ (1 − d) (min_i Q̄_i(s', a') − α log π(a'|s')), a' ~ π(·|s')  (eq. 3,
    // 5)
    sample_policy(batch_.next_observations, sample_rng(), exploration_, next_);
    concatenate_rows(batch_.next_observations, actions_of(next_), critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/true);
    Eigen::VectorXf targets = (critics_.values().colwise().minCoeff().transpose().array() -
                               ent_coef * log_probs_of(next_).array())
                                  .matrix();
    targets =
        (batch_.rewards.array() + gamma * (1.0f - batch_.terminated.array()) * targets.array())
            .matrix();
    if (config_.q_clip) {
      const auto clip = static_cast<float>(*config_.q_clip);
      targets = targets.cwiseMax(-clip).cwiseMin(clip);
    }

    // Critic step on ½ Σ_i mean (Q_i(s, a) − y)².
    concatenate_rows(batch_.observations, batch_.actions, critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/false);
    value_gradient_ = (critics_.values().rowwise() - targets.transpose()) * inverse_batch;
    critic_loss_sum += 0.5 * static_cast<double>(value_gradient_.squaredNorm()) * batch_size;
    critics_.backward(value_gradient_, /*parameters=*/true, nullptr);
    critics_.step(learning_rate);

    // Actor step on mean(α log π(a|s) − min_i Q_i(s, a)), a = tanh(μ + σ ε)  (eq. 12), through
    // the just-updated critics.
    concatenate_rows(batch_.observations, actions_of(current_), critic_inputs_);
    critics_.forward(critic_inputs_, /*target=*/false);
    const Eigen::MatrixXf& q = critics_.values();
    value_gradient_.setZero(q.rows(), q.cols());
    double min_q_sum = 0.0;
    for (Eigen::Index i = 0; i < q.cols(); ++i) {
      Eigen::Index argmin;
      min_q_sum += q.col(i).minCoeff(&argmin);
      value_gradient_(argmin, i) = -inverse_batch;
    }
    actor_loss_sum += ent_coef * static_cast<double>(log_probs_of(current_).mean()) -
                      min_q_sum / static_cast<double>(batch_size);
    critics_.backward(value_gradient_, /*parameters=*/false, &input_gradient_);

    const auto network = actor_.parameter_count();
    if (config_.use_sde) {
      Eigen::Map<Eigen::MatrixXf> log_std_gradient(actor_gradient_.data() + network, latent_size_,
                                                   a);
      current_.sde.gradients(current_.tape.output(), latent_of(current_.tape), log_std(),
                             input_gradient_.bottomRows(a), ent_coef, actor_output_gradient_,
                             log_std_gradient);
    } else {
      current_.gaussian.head_gradient(current_.tape.output(), input_gradient_.bottomRows(a),
                                      ent_coef, actor_output_gradient_);
    }
    actor_.backward(actor_parameters_.head(network), current_.tape, actor_output_gradient_,
                    actor_gradient_.head(network), nullptr, actor_scratch_);
    actor_optimizer_.set_learning_rate(learning_rate);
    actor_optimizer_.step(actor_parameters_, actor_gradient_);
    actor_gradient_.setZero();

    count_update();
    if (gradient_updates() % config_.target_update_interval == 0) {
      critics_.update_target(config_.common.tau);
    }
  }
  const auto n = static_cast<double>(gradient_steps);
  TrainStats stats{{"train/actor_loss", actor_loss_sum / n},
                   {"train/critic_loss", critic_loss_sum / n},
                   {"train/ent_coef", ent_coef_sum / n},
                   {"train/learning_rate", learning_rate}};
  if (config_.auto_entropy) stats.emplace_back("train/ent_coef_loss", ent_loss_sum / n);
  return stats;
}

void Sac::save_state(CheckpointWriter& writer) const {
  writer.write_floats("actor_parameters", actor_parameters_);
  save_adam(writer, "actor_adam", actor_optimizer_);
  critics_.save(writer, "critics");
  writer.write_floats("log_ent_coef", log_ent_coef_);
  save_adam(writer, "ent_coef_adam", ent_coef_optimizer_);
}

std::function<void()> Sac::prepare_load(CheckpointReader& reader) {
  Eigen::VectorXf actor = reader.read_floats("actor_parameters", actor_parameters_.size());
  auto install_actor_adam =
      prepare_adam(reader, "actor_adam", actor_optimizer_, actor_parameters_.size());
  auto install_critics = critics_.prepare_load(reader, "critics");
  Eigen::VectorXf log_ent_coef = reader.read_floats("log_ent_coef", 1);
  auto install_ent_adam = prepare_adam(reader, "ent_coef_adam", ent_coef_optimizer_, 1);
  return [=, this] {
    actor_parameters_ = actor;
    install_actor_adam();
    install_critics();
    log_ent_coef_ = log_ent_coef;
    install_ent_adam();
  };
}

}  // namespace tendril::rl
