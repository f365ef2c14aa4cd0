#include "tendril/safety/constraint.hpp"

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

// Observation [x, ẋ, t/T].
class DoubleIntegratorConstraint : public Constraint {
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

// Observation [x, y, cos ψ, sin ψ, t/T].
class DubinsCarConstraint : public Constraint {
 public:
  explicit DubinsCarConstraint(const DubinsCar::Params& params) : params_(params) {}
  double margin(const Observation& o) const override {
    return DubinsCar::safety_margin(params_, o[0], o[1]);
  }
  double max_margin() const override { return DubinsCar::max_safety_margin(params_); }
  int64_t time_step(const Observation& o) const override {
    return std::llround(static_cast<double>(o[4]) * params_.horizon);
  }
  int64_t horizon() const override { return params_.horizon; }
  Observation sample_unsafe(Rng& rng) const override {
    Observation o(5);
    const double a = params_.absolute_limit;
    do {
      const double heading = rng.uniform(-std::numbers::pi, std::numbers::pi);
      o << static_cast<float>(rng.uniform(-a, a)), static_cast<float>(rng.uniform(-a, a)),
          static_cast<float>(std::cos(heading)), static_cast<float>(std::sin(heading)),
          static_cast<float>(rng.below(params_.horizon + 1)) / static_cast<float>(params_.horizon);
    } while (!unsafe(o));
    return o;
  }

 private:
  DubinsCar::Params params_;
};

// Observation [θx, θy, θ̇x, θ̇y, t/T] of the limb's safety task: d = R − ‖θ‖ (the author's
// l(x) = (30 − ‖θ‖)/30), unsafe draws over [−100, 100]⁴ as the author's code samples them.
class LearnedLimbConstraint : public Constraint {
 public:
  explicit LearnedLimbConstraint(const LearnedSafetyEnv::Params& params) : params_(params) {}
  double margin(const Observation& o) const override {
    return LearnedSafetyEnv::safety_margin(params_, o[0], o[1]);
  }
  double max_margin() const override { return params_.safe_radius; }
  int64_t time_step(const Observation& o) const override {
    return std::llround(static_cast<double>(o[4]) * params_.horizon);
  }
  int64_t horizon() const override { return params_.horizon; }
  Observation sample_unsafe(Rng& rng) const override {
    Observation o(5);
    const double v = params_.velocity_limit;
    do {
      for (int i = 0; i < 4; ++i) o[i] = static_cast<float>(rng.uniform(-v, v));
      o[4] =
          static_cast<float>(rng.below(params_.horizon + 1)) / static_cast<float>(params_.horizon);
    } while (!unsafe(o));
    return o;
  }

 private:
  LearnedSafetyEnv::Params params_;
};

}  // namespace

std::unique_ptr<Constraint> constraint_of(Env& env) {
  if (const auto* di = envs::find_wrapper<DoubleIntegrator>(env)) {
    return std::make_unique<DoubleIntegratorConstraint>(di->params());
  }
  if (const auto* car = envs::find_wrapper<DubinsCar>(env)) {
    return std::make_unique<DubinsCarConstraint>(car->params());
  }
  if (const auto* limb = envs::find_wrapper<LearnedSafetyEnv>(env)) {
    return std::make_unique<LearnedLimbConstraint>(limb->params());
  }
  throw Error("the environment has no safety constraint (safe-control environments have one)",
              "safety::constraint_of");
}

}  // namespace tendril::safety
