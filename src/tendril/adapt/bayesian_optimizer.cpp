#include "tendril/adapt/bayesian_optimizer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

#include "tendril/adapt/box_maximizer.hpp"
#include "tendril/adapt/number_text.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

// L-BFGS budget for each climb of the acquisition.
constexpr int kAcquisitionEvaluations = 100;
constexpr double kAcquisitionTolerance = 1e-9;

double standard_normal_cdf(double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); }
double standard_normal_pdf(double z) {
  return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
}

}  // namespace

GpOptions default_surrogate_options() {
  GpOptions options;
  options.kernel = KernelType::matern52;
  options.min_length_scale = 1e-2;
  options.max_length_scale = 1e2;
  options.min_noise_variance = 1e-8;
  options.max_noise_variance = 1e-1;
  options.restarts = 2;
  return options;
}

BayesianOptimizer::BayesianOptimizer(BayesOptOptions options)
    : options_(std::move(options)),
      rng_(options_.seed),
      surrogate_(std::max<int>(1, static_cast<int>(options_.lower.size())), options_.surrogate) {
  const std::string where = "BayesianOptimizer";
  const auto d = options_.lower.size();
  if (d == 0 || options_.upper.size() != d) {
    throw Error("lower and upper bounds must have the same positive size (got " +
                    std::to_string(d) + " and " + std::to_string(options_.upper.size()) + ")",
                where);
  }
  for (Eigen::Index j = 0; j < d; ++j) {
    if (!(options_.lower[j] < options_.upper[j]) || !std::isfinite(options_.lower[j]) ||
        !std::isfinite(options_.upper[j])) {
      throw Error("bounds of dimension " + std::to_string(j) + " are [" +
                      number_text(options_.lower[j]) + ", " + number_text(options_.upper[j]) +
                      "] (need finite lower < upper)",
                  where);
    }
  }
  require(options_.initial_points >= 1, "initial_points must be at least 1", where);
  require(options_.acquisition_candidates >= 1 && options_.acquisition_restarts >= 1,
          "acquisition_candidates and acquisition_restarts must be at least 1", where);
  require(options_.exploration >= 0.0 && options_.confidence >= 0.0,
          "exploration and confidence must be non-negative", where);
}

Eigen::VectorXd BayesianOptimizer::to_unit(const Eigen::VectorXd& point) const {
  return (point - options_.lower).cwiseQuotient(options_.upper - options_.lower);
}

Eigen::VectorXd BayesianOptimizer::from_unit(const Eigen::VectorXd& unit) const {
  return options_.lower + unit.cwiseProduct(options_.upper - options_.lower);
}

const Eigen::VectorXd& BayesianOptimizer::best_point() const {
  require(best_ >= 0, "no value told yet", "BayesianOptimizer::best_point");
  return points_[best_];
}

double BayesianOptimizer::best_value() const {
  require(best_ >= 0, "no value told yet", "BayesianOptimizer::best_value");
  return values_[best_];
}

void BayesianOptimizer::tell(const Eigen::VectorXd& point, double value) {
  const std::string where = "BayesianOptimizer::tell";
  const auto d = options_.lower.size();
  if (point.size() != d) {
    throw Error(
        "point has " + std::to_string(point.size()) + " values, expected " + std::to_string(d),
        where);
  }
  const Eigen::VectorXd unit = to_unit(point);
  if (!unit.allFinite() || (unit.array() < -1e-9).any() || (unit.array() > 1.0 + 1e-9).any()) {
    throw Error("point lies outside the box", where);
  }
  if (!std::isfinite(value)) {
    throw Error(
        "value of evaluation " + std::to_string(evaluations()) + " is " + number_text(value),
        where);
  }
  points_.push_back(point);
  values_.push_back(value);
  surrogate_.add(unit.cwiseMax(0.0).cwiseMin(1.0), value);
  if (best_ < 0 || value < values_[best_]) best_ = evaluations() - 1;
  const Eigen::Map<const Eigen::VectorXd> seen(values_.data(), evaluations());
  exploration_ = options_.exploration * std::sqrt((seen.array() - seen.mean()).square().mean());
}

double BayesianOptimizer::unit_acquisition(const Eigen::VectorXd& unit,
                                           Eigen::VectorXd* gradient) const {
  double mean = 0.0, variance = 0.0;
  Eigen::VectorXd mean_gradient, variance_gradient;
  surrogate_.predict(unit, mean, variance, mean_gradient, variance_gradient);
  const double sigma = std::sqrt(variance);
  // ∂σ/∂x = (∂σ²/∂x) / 2σ; a vanishing σ (at a point already seen) has no usable gradient.
  const bool has_spread = sigma > 1e-12 * std::sqrt(surrogate_.hyperparameters().signal_variance);
  Eigen::VectorXd sigma_gradient = has_spread ? Eigen::VectorXd(variance_gradient / (2.0 * sigma))
                                              : Eigen::VectorXd::Zero(unit.size());
  double value = 0.0;
  if (options_.acquisition == Acquisition::upper_confidence_bound) {
    value = -mean + options_.confidence * sigma;
    if (gradient) *gradient = -mean_gradient + options_.confidence * sigma_gradient;
    return value;
  }
  const double improvement = values_[best_] - exploration_ - mean;
  if (!has_spread) {
    value = std::max(improvement, 0.0);
    if (gradient) {
      *gradient =
          improvement > 0.0 ? Eigen::VectorXd(-mean_gradient) : Eigen::VectorXd::Zero(unit.size());
    }
    return value;
  }
  const double z = improvement / sigma;
  const double cdf = standard_normal_cdf(z), pdf = standard_normal_pdf(z);
  // ∂EI/∂μ = −Φ(z), ∂EI/∂σ = φ(z).
  value = improvement * cdf + sigma * pdf;
  if (gradient) *gradient = -cdf * mean_gradient + pdf * sigma_gradient;
  return value;
}

double BayesianOptimizer::acquisition(const Eigen::VectorXd& point,
                                      Eigen::VectorXd* gradient) const {
  require(best_ >= 0, "no value told yet", "BayesianOptimizer::acquisition");
  require(point.size() == options_.lower.size(), "point has the wrong size",
          "BayesianOptimizer::acquisition");
  const double value = unit_acquisition(to_unit(point), gradient);
  if (gradient) *gradient = gradient->cwiseQuotient(options_.upper - options_.lower);
  return value;
}

Eigen::VectorXd BayesianOptimizer::ask() {
  const auto d = static_cast<int>(options_.lower.size());
  Eigen::VectorXd unit(d);
  const auto draw = [&] {
    for (int j = 0; j < d; ++j) unit[j] = rng_.uniform();
    return unit;
  };
  if (evaluations() < options_.initial_points) return from_unit(draw());

  surrogate_.optimize_hyperparameters(rng_);
  const int candidates = options_.acquisition_candidates;
  std::vector<Eigen::VectorXd> starts(candidates);
  std::vector<double> scores(candidates);
  for (int c = 0; c < candidates; ++c) {
    starts[c] = draw();
    scores[c] = unit_acquisition(starts[c], nullptr);
  }
  std::vector<int> order(candidates);
  std::iota(order.begin(), order.end(), 0);
  const int climbs = std::min(options_.acquisition_restarts, candidates);
  std::partial_sort(order.begin(), order.begin() + climbs, order.end(),
                    [&](int a, int b) { return scores[a] > scores[b]; });

  const SmoothObjective objective = [this](const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
    return unit_acquisition(x, &gradient);
  };
  const Eigen::VectorXd zeros = Eigen::VectorXd::Zero(d), ones = Eigen::VectorXd::Ones(d);
  Eigen::VectorXd best_unit = starts[order[0]];
  double best_score = scores[order[0]];
  for (int k = 0; k < climbs; ++k) {
    const BoxMaximum found = maximize_in_box(objective, zeros, ones, starts[order[k]],
                                             kAcquisitionEvaluations, kAcquisitionTolerance);
    if (found.value > best_score) {
      best_score = found.value;
      best_unit = found.point;
    }
  }
  return from_unit(best_unit);
}

BayesOptResult bayes_minimize(const std::function<double(const Eigen::VectorXd&)>& objective,
                              const BayesOptOptions& options, int budget) {
  require(budget >= 1, "the budget must be at least one evaluation", "bayes_minimize");
  BayesianOptimizer optimizer(options);
  for (int i = 0; i < budget; ++i) {
    const Eigen::VectorXd point = optimizer.ask();
    optimizer.tell(point, objective(point));
  }
  return {optimizer.best_point(), optimizer.best_value(), optimizer.points(), optimizer.values()};
}

}  // namespace tendril::adapt
