#include "tendril/safety/lagrangian_penalty.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/rl/adam_checkpoint.hpp"

namespace tendril::safety {

namespace {

// log ν stays finite: e^±30 is far beyond any multiplier a run needs.
constexpr float kLogMultiplierBound = 30.0f;

}  // namespace

MultiplierSettings MultiplierSettings::from_config(const std::string& method,
                                                   const Config& config) {
  MultiplierSettings s;
  if (method == "lagrangian") {
    s.kind = Kind::kLearned;
    s.initial = config.get_or("initial", s.initial);
    s.learning_rate = config.get_or("learning_rate", s.learning_rate);
    require(s.initial > 0.0, "must be positive", config.where("initial"));
    require(s.learning_rate > 0.0, "must be positive", config.where("learning_rate"));
  } else if (method == "rspo") {
    s.kind = Kind::kScheduled;
    s.start = config.get_or("start", s.start);
    s.end = config.get_or("end", s.end);
    require(s.start >= 0.0 && s.end >= 0.0, "must be non-negative", config.where("start/end"));
  } else {
    throw Error("the method is 'lagrangian' or 'rspo', not '" + method + "'",
                config.where("method"));
  }
  return s;
}

LagrangianPenalty::LagrangianPenalty(CostCritic& critic, double cost_limit,
                                     const MultiplierSettings& multiplier, int64_t total_timesteps)
    : critic_(critic),
      cost_limit_(cost_limit),
      settings_(multiplier),
      total_timesteps_(total_timesteps),
      log_multiplier_(Eigen::VectorXf::Constant(
          1, static_cast<float>(std::log(std::max(multiplier.initial, 1e-12))))),
      optimizer_(1, {multiplier.learning_rate}) {
  require(total_timesteps > 0, "the budget must be positive", "LagrangianPenalty");
}

double LagrangianPenalty::multiplier() const {
  if (settings_.kind == MultiplierSettings::Kind::kLearned) {
    return std::exp(static_cast<double>(log_multiplier_[0]));
  }
  const double done =
      std::clamp(static_cast<double>(timesteps_) / static_cast<double>(total_timesteps_), 0.0, 1.0);
  return settings_.start + (settings_.end - settings_.start) * done;
}

double LagrangianPenalty::add_gradient(const Eigen::MatrixXf& observations,
                                       const Eigen::MatrixXf& actions,
                                       Eigen::Ref<Eigen::MatrixXf> action_gradient) {
  const double nu = multiplier();
  const Eigen::VectorXf& risk = critic_.values(observations, actions);
  last_cost_value_ = static_cast<double>(risk.mean());
  const auto batch = static_cast<float>(risk.size());
  critic_.add_action_gradient(static_cast<float>(nu) / batch, action_gradient);
  if (settings_.kind == MultiplierSettings::Kind::kLearned) {
    // Dual descent on the loss log ν · (ε_risk − E[Q_risk]) (Recovery RL's LR).
    Eigen::VectorXf gradient =
        Eigen::VectorXf::Constant(1, static_cast<float>(cost_limit_ - last_cost_value_));
    optimizer_.step(log_multiplier_, gradient);
    log_multiplier_[0] = std::clamp(log_multiplier_[0], -kLogMultiplierBound, kLogMultiplierBound);
  }
  return nu * (last_cost_value_ - cost_limit_);
}

void LagrangianPenalty::save(ArchiveWriter& writer, const std::string& prefix) const {
  writer.put(prefix + "timesteps", timesteps_);
  writer.put_floats(prefix + "log_multiplier", log_multiplier_);
  rl::save_adam(writer, prefix + "adam", optimizer_);
  writer.put(prefix + "last_cost_value", last_cost_value_);
}

std::function<void()> LagrangianPenalty::prepare_load(const ArchiveReader& reader,
                                                      const std::string& prefix) {
  const int64_t timesteps = reader.get_int(prefix + "timesteps");
  require(timesteps >= 0, "a negative step count", reader.name());
  const Eigen::VectorXf log_multiplier = reader.get_floats(prefix + "log_multiplier", 1);
  std::function<void()> install_adam = rl::prepare_adam(reader, prefix + "adam", optimizer_, 1);
  const double last_cost_value = reader.get_double(prefix + "last_cost_value");
  return [this, timesteps, log_multiplier, install_adam, last_cost_value] {
    timesteps_ = timesteps;
    log_multiplier_ = log_multiplier;
    install_adam();
    last_cost_value_ = last_cost_value;
  };
}

}  // namespace tendril::safety
