// The double integrator as a SafetyTask: its constraint and search space (seed 001 §6.4.1).
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/envs/safe_control/double_integrator.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs::safe_control {
namespace {

// Observation [x, ẋ, t/T].
class DoubleIntegratorConstraint : public SafetyConstraint {
 public:
  explicit DoubleIntegratorConstraint(const DoubleIntegrator::Params& params) : params_(params) {}
  double margin(const Observation& o) const override {
    return DoubleIntegrator::safety_margin(params_, o[0], o[1]);
  }
  double max_margin() const override { return DoubleIntegrator::max_safety_margin(params_); }
  int64_t time_step(const Observation& o) const override {
    return std::llround(static_cast<double>(o[2]) * params_.horizon);
  }
  int64_t horizon() const override { return params_.horizon; }
  Observation sample_unsafe(Rng& rng) const override {
    Observation o(3);
    do {
      o << static_cast<float>(
          rng.uniform(-params_.absolute_position_limit, params_.absolute_position_limit)),
          static_cast<float>(
              rng.uniform(-params_.absolute_velocity_limit, params_.absolute_velocity_limit)),
          static_cast<float>(rng.below(params_.horizon + 1)) / static_cast<float>(params_.horizon);
    } while (!unsafe(o));
    return o;
  }

 private:
  DoubleIntegrator::Params params_;
};

// (x, ẋ) in units of the safe bounds.
class DoubleIntegratorSpace : public SafetySearchSpace {
 public:
  explicit DoubleIntegratorSpace(const DoubleIntegrator::Params& params)
      : params_(params), names_{"position", "velocity"}, scales_(2) {
    scales_ << params.position_limit, params.velocity_limit;
  }
  const std::vector<std::string>& names() const override { return names_; }
  const Eigen::VectorXd& scales() const override { return scales_; }
  Observation observation(const Eigen::VectorXd& s) const override {
    return Eigen::Vector3f(static_cast<float>(s[0] * scales_[0]),
                           static_cast<float>(s[1] * scales_[1]), 0.0f);
  }
  void place(Env& env, const Eigen::VectorXd& s) const override {
    auto* di = find_wrapper<DoubleIntegrator>(env);
    require(di != nullptr, "not a double integrator", "SafetySearchSpace::place");
    di->set_state(s[0] * scales_[0], s[1] * scales_[1]);
  }
  Eigen::VectorXd sample(Rng& rng) const override {
    Eigen::Vector2d s;
    s << rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0);  // drawn left to right
    return s;
  }
  std::optional<bool> analytically_safe(const Eigen::VectorXd& s) const override {
    return DoubleIntegrator::in_analytic_safe_set(params_, s[0] * scales_[0], s[1] * scales_[1]);
  }

 private:
  DoubleIntegrator::Params params_;
  std::vector<std::string> names_;
  Eigen::VectorXd scales_;
};

}  // namespace

std::unique_ptr<SafetyConstraint> DoubleIntegrator::safety_constraint() const {
  return std::make_unique<DoubleIntegratorConstraint>(params_);
}

std::unique_ptr<SafetySearchSpace> DoubleIntegrator::safety_search_space() const {
  return std::make_unique<DoubleIntegratorSpace>(params_);
}

}  // namespace tendril::envs::safe_control
