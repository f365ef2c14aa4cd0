// The Dubins car as a SafetyTask: its constraint and search space (seed 001 §6.4.1).
#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"
#include "tendril/envs/safe_control/dubins_car.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs::safe_control {
namespace {

// Observation [x, y, cos ψ, sin ψ, t/T].
class DubinsCarConstraint : public SafetyConstraint {
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
    const double a = params_.absolute_limit;
    Observation o;
    do {  // the draws in the order the five-entry observation always took them
      const double heading = rng.uniform(-std::numbers::pi, std::numbers::pi);
      const double x = rng.uniform(-a, a), y = rng.uniform(-a, a);
      const float time =
          static_cast<float>(rng.below(params_.horizon + 1)) / static_cast<float>(params_.horizon);
      o = DubinsCar::observation_of(params_, x, y, heading, time);
    } while (!unsafe(o));
    return o;
  }

 private:
  DubinsCar::Params params_;
};

// (x, y, ψ) in units of (box, box, π); samples over the box with any heading (some land in the
// keep-out disc, whose values are negative and are redrawn by the search).
class DubinsCarSpace : public SafetySearchSpace {
 public:
  explicit DubinsCarSpace(const DubinsCar::Params& params)
      : params_(params), names_{"x", "y", "heading"}, scales_(3) {
    scales_ << params.box_limit, params.box_limit, std::numbers::pi;
  }
  const std::vector<std::string>& names() const override { return names_; }
  const Eigen::VectorXd& scales() const override { return scales_; }
  Observation observation(const Eigen::VectorXd& s) const override {
    return DubinsCar::observation_of(params_, s[0] * scales_[0], s[1] * scales_[1],
                                     s[2] * scales_[2], 0.0f);
  }
  void place(Env& env, const Eigen::VectorXd& s) const override {
    auto* car = find_wrapper<DubinsCar>(env);
    require(car != nullptr, "not a Dubins car", "SafetySearchSpace::place");
    car->set_state(s[0] * scales_[0], s[1] * scales_[1], s[2] * scales_[2]);
  }
  Eigen::VectorXd sample(Rng& rng) const override {
    Eigen::Vector3d s;
    s << rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0);
    return s;
  }

 private:
  DubinsCar::Params params_;
  std::vector<std::string> names_;
  Eigen::VectorXd scales_;
};

}  // namespace

std::unique_ptr<SafetyConstraint> DubinsCar::safety_constraint() const {
  return std::make_unique<DubinsCarConstraint>(params_);
}

std::unique_ptr<SafetySearchSpace> DubinsCar::safety_search_space() const {
  return std::make_unique<DubinsCarSpace>(params_);
}

}  // namespace tendril::envs::safe_control
