// The limb's safety task as a SafetyTask: its constraint and search space (seed 001 §6.5).
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/envs/sma_limb/learned_safety_env.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs::sma_limb {
namespace {

// Observation [θx, θy, θ̇x, θ̇y, t/T]: d = R − ‖θ‖ (the author's l(x) = (30 − ‖θ‖)/30), unsafe
// draws over [−100, 100]⁴ as the author's code samples them.
class LearnedLimbConstraint : public SafetyConstraint {
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

// (θx, θy, θ̇x, θ̇y) in units of the safe radius (degrees, and degrees per second).
class LearnedLimbSpace : public SafetySearchSpace {
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
    auto* limb = find_wrapper<LearnedSafetyEnv>(env);
    require(limb != nullptr, "not the limb's safety task", "SafetySearchSpace::place");
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

std::unique_ptr<SafetyConstraint> LearnedSafetyEnv::safety_constraint() const {
  return std::make_unique<LearnedLimbConstraint>(params_);
}

std::unique_ptr<SafetySearchSpace> LearnedSafetyEnv::safety_search_space() const {
  return std::make_unique<LearnedLimbSpace>(params_);
}

}  // namespace tendril::envs::sma_limb
