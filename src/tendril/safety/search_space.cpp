#include "tendril/safety/search_space.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"
#include "tendril/envs/safe_control/double_integrator.hpp"
#include "tendril/envs/safe_control/dubins_car.hpp"
#include "tendril/envs/sma_limb/learned_safety_env.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::safety {
namespace {

using envs::safe_control::DoubleIntegrator;
using envs::safe_control::DubinsCar;
using envs::sma_limb::LearnedSafetyEnv;

// (x, ẋ) in units of the safe bounds.
class DoubleIntegratorSpace : public SearchSpace {
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
    auto* di = envs::find_wrapper<DoubleIntegrator>(env);
    require(di != nullptr, "not a double integrator", "SearchSpace::place");
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

// (x, y, ψ) in units of (box, box, π); samples over the box with any heading (some land in the
// keep-out disc, whose values are negative and are redrawn by the search).
class DubinsCarSpace : public SearchSpace {
 public:
  explicit DubinsCarSpace(const DubinsCar::Params& params)
      : names_{"x", "y", "heading"}, scales_(3) {
    scales_ << params.box_limit, params.box_limit, std::numbers::pi;
  }
  const std::vector<std::string>& names() const override { return names_; }
  const Eigen::VectorXd& scales() const override { return scales_; }
  Observation observation(const Eigen::VectorXd& s) const override {
    const double heading = s[2] * scales_[2];
    Observation o(5);
    o << static_cast<float>(s[0] * scales_[0]), static_cast<float>(s[1] * scales_[1]),
        static_cast<float>(std::cos(heading)), static_cast<float>(std::sin(heading)), 0.0f;
    return o;
  }
  void place(Env& env, const Eigen::VectorXd& s) const override {
    auto* car = envs::find_wrapper<DubinsCar>(env);
    require(car != nullptr, "not a Dubins car", "SearchSpace::place");
    car->set_state(s[0] * scales_[0], s[1] * scales_[1], s[2] * scales_[2]);
  }
  Eigen::VectorXd sample(Rng& rng) const override {
    Eigen::Vector3d s;
    s << rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0);
    return s;
  }

 private:
  std::vector<std::string> names_;
  Eigen::VectorXd scales_;
};

// (θx, θy, θ̇x, θ̇y) in units of the safe radius (degrees, and degrees per second).
class LearnedLimbSpace : public SearchSpace {
 public:
  explicit LearnedLimbSpace(const LearnedSafetyEnv::Params& params)
      : names_{"theta_x", "theta_y", "theta_dot_x", "theta_dot_y"},
        scales_(Eigen::VectorXd::Constant(4, params.safe_radius)) {}
  const std::vector<std::string>& names() const override { return names_; }
  const Eigen::VectorXd& scales() const override { return scales_; }
  Observation observation(const Eigen::VectorXd& s) const override {
    Observation o(5);
    o << (s.array() * scales_.array()).cast<float>().matrix(), 0.0f;
    return o;
  }
  void place(Env& env, const Eigen::VectorXd& s) const override {
    auto* limb = envs::find_wrapper<LearnedSafetyEnv>(env);
    require(limb != nullptr, "not the limb's safety task", "SearchSpace::place");
    limb->set_state((s.array() * scales_.array()).matrix());
  }
  Eigen::VectorXd sample(Rng& rng) const override {
    Eigen::VectorXd s(4);
    for (int i = 0; i < 4; ++i) s[i] = rng.uniform(-1.0, 1.0);
    return s;
  }

 private:
  std::vector<std::string> names_;
  Eigen::VectorXd scales_;
};

}  // namespace

std::unique_ptr<SearchSpace> search_space_of(Env& env) {
  if (const auto* di = envs::find_wrapper<DoubleIntegrator>(env)) {
    return std::make_unique<DoubleIntegratorSpace>(di->params());
  }
  if (const auto* car = envs::find_wrapper<DubinsCar>(env)) {
    return std::make_unique<DubinsCarSpace>(car->params());
  }
  if (const auto* limb = envs::find_wrapper<LearnedSafetyEnv>(env)) {
    return std::make_unique<LearnedLimbSpace>(limb->params());
  }
  throw Error(
      "the environment has no search space for the safety filter's tools (safe-control "
      "environments and the limb's safety task have one)",
      "safety::search_space_of");
}

}  // namespace tendril::safety
