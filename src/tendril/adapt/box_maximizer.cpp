#include "tendril/adapt/box_maximizer.hpp"

#include <nlopt.h>

#include <cmath>
#include <exception>
#include <limits>
#include <memory>

#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

struct Context {
  const SmoothObjective* objective;
  Eigen::VectorXd x, gradient;
  BoxMaximum best;
  std::exception_ptr failure;
  nlopt_opt opt = nullptr;
};

// NLopt's C callback: no exception may cross it, so a failure is kept and NLopt is stopped.
double trampoline(unsigned n, const double* x, double* gradient, void* data) {
  auto& context = *static_cast<Context*>(data);
  try {
    context.x = Eigen::Map<const Eigen::VectorXd>(x, n);
    const double value = (*context.objective)(context.x, context.gradient);
    ++context.best.evaluations;
    if (gradient) Eigen::Map<Eigen::VectorXd>(gradient, n) = context.gradient;
    if (std::isfinite(value) && value > context.best.value) {
      context.best.value = value;
      context.best.point = context.x;
    }
    return value;
  } catch (...) {
    context.failure = std::current_exception();
    nlopt_force_stop(context.opt);
    return 0.0;
  }
}

struct OptDeleter {
  void operator()(nlopt_opt opt) const { nlopt_destroy(opt); }
};

}  // namespace

BoxMaximum maximize_in_box(const SmoothObjective& objective, const Eigen::VectorXd& lower,
                           const Eigen::VectorXd& upper, const Eigen::VectorXd& start,
                           int max_evaluations, double relative_tolerance) {
  const auto n = static_cast<unsigned>(start.size());
  require(lower.size() == start.size() && upper.size() == start.size(),
          "bounds and start differ in size", "maximize_in_box");
  require((lower.array() <= upper.array()).all(), "a lower bound exceeds its upper bound",
          "maximize_in_box");
  Context context{&objective, Eigen::VectorXd(n), Eigen::VectorXd(n), {}, nullptr};
  context.best.value = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd x = start.cwiseMax(lower).cwiseMin(upper);
  context.best.point = x;

  std::unique_ptr<nlopt_opt_s, OptDeleter> opt(nlopt_create(NLOPT_LD_LBFGS, n));
  require(opt != nullptr, "NLopt could not create an L-BFGS optimiser", "maximize_in_box");
  context.opt = opt.get();
  nlopt_set_lower_bounds(opt.get(), lower.data());
  nlopt_set_upper_bounds(opt.get(), upper.data());
  nlopt_set_max_objective(opt.get(), trampoline, &context);
  nlopt_set_maxeval(opt.get(), max_evaluations);
  nlopt_set_ftol_rel(opt.get(), relative_tolerance);
  double value = 0.0;
  nlopt_optimize(opt.get(), x.data(), &value);
  if (context.failure) std::rethrow_exception(context.failure);
  if (context.best.evaluations == 0) {
    // NLopt returned before evaluating (e.g. a zero-width box): the start is the answer.
    context.best.value = objective(context.best.point, context.gradient);
    context.best.evaluations = 1;
  }
  return context.best;
}

}  // namespace tendril::adapt
