#include "tendril/adapt/adapt_config.hpp"

#include <string>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

std::string where(const Config& config, const char* key) {
  return config.source() + ": " + (config.path().empty() ? "" : config.path() + ".") + key;
}

void check(bool condition, const Config& config, const char* key, const char* what) {
  if (!condition) throw Error(what, where(config, key));
}

// A [min, max] pair of positive numbers with min <= max.
void read_bounds(const Config& config, const char* key, double& low, double& high) {
  if (!config.has(key)) return;
  const auto values = config.get<std::vector<double>>(key);
  check(values.size() == 2, config, key, "expected [min, max]");
  check(0.0 < values[0] && values[0] <= values[1], config, key,
        "bounds must be positive with min <= max");
  low = values[0];
  high = values[1];
}

Eigen::VectorXd read_vector(const Config& config, const char* key,
                            const Eigen::VectorXd& fallback) {
  if (!config.has(key)) return fallback;
  const auto values = config.get<std::vector<double>>(key);
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

}  // namespace

GpOptions read_gp_options(const Config& config, GpOptions defaults) {
  GpOptions options = defaults;
  if (config.has("kernel")) {
    options.kernel =
        kernel_type_from_name(config.get<std::string>("kernel"), where(config, "kernel"));
  }
  options.mean_of_targets = config.get_or<bool>("mean_of_targets", options.mean_of_targets);
  options.window = config.get_or<int>("window", options.window);
  check(options.window >= 0, config, "window", "must be non-negative (0: keep every point)");
  options.restarts = config.get_or<int>("restarts", options.restarts);
  check(options.restarts >= 0, config, "restarts", "must be non-negative");
  options.max_evaluations = config.get_or<int>("max_evaluations", options.max_evaluations);
  check(options.max_evaluations >= 1, config, "max_evaluations", "must be at least 1");
  options.relative_tolerance =
      config.get_or<double>("relative_tolerance", options.relative_tolerance);
  check(options.relative_tolerance >= 0.0, config, "relative_tolerance", "must be non-negative");
  read_bounds(config, "length_scale_bounds", options.min_length_scale, options.max_length_scale);
  read_bounds(config, "signal_variance_bounds", options.min_signal_variance,
              options.max_signal_variance);
  read_bounds(config, "noise_variance_bounds", options.min_noise_variance,
              options.max_noise_variance);
  config.reject_unknown();
  return options;
}

BayesOptOptions read_bayes_opt_options(const Config& config, BayesOptOptions defaults) {
  BayesOptOptions options = defaults;
  options.lower = read_vector(config, "lower", options.lower);
  options.upper = read_vector(config, "upper", options.upper);
  check(options.lower.size() > 0 && options.lower.size() == options.upper.size(), config, "upper",
        "lower and upper must be lists of the same positive length");
  check((options.lower.array() < options.upper.array()).all(), config, "upper",
        "every upper bound must exceed its lower bound");
  options.initial_points = config.get_or<int>("initial_points", options.initial_points);
  check(options.initial_points >= 1, config, "initial_points", "must be at least 1");
  if (config.has("acquisition")) {
    const auto name = config.get<std::string>("acquisition");
    if (name == "expected_improvement") {
      options.acquisition = Acquisition::expected_improvement;
    } else if (name == "upper_confidence_bound") {
      options.acquisition = Acquisition::upper_confidence_bound;
    } else {
      throw Error("unknown acquisition '" + name +
                      "' (expected expected_improvement or upper_confidence_bound)",
                  where(config, "acquisition"));
    }
  }
  options.exploration = config.get_or<double>("exploration", options.exploration);
  check(options.exploration >= 0.0, config, "exploration", "must be non-negative");
  options.confidence = config.get_or<double>("confidence", options.confidence);
  check(options.confidence >= 0.0, config, "confidence", "must be non-negative");
  options.acquisition_candidates =
      config.get_or<int>("acquisition_candidates", options.acquisition_candidates);
  check(options.acquisition_candidates >= 1, config, "acquisition_candidates",
        "must be at least 1");
  options.acquisition_restarts =
      config.get_or<int>("acquisition_restarts", options.acquisition_restarts);
  check(options.acquisition_restarts >= 1, config, "acquisition_restarts", "must be at least 1");
  options.seed = config.get_or<uint64_t>("seed", options.seed);
  if (config.has("surrogate")) {
    options.surrogate = read_gp_options(config.child("surrogate"), options.surrogate);
  }
  config.reject_unknown();
  return options;
}

KMeansOptions read_kmeans_options(const Config& config, KMeansOptions defaults) {
  KMeansOptions options = defaults;
  options.clusters = config.get_or<int>("clusters", options.clusters);
  check(options.clusters >= 1, config, "clusters", "must be at least 1");
  if (config.has("init")) {
    options.init = kmeans_init_from_name(config.get<std::string>("init"), where(config, "init"));
  }
  options.restarts = config.get_or<int>("restarts", options.restarts);
  check(options.restarts >= 1, config, "restarts", "must be at least 1");
  options.max_iterations = config.get_or<int>("max_iterations", options.max_iterations);
  check(options.max_iterations >= 1, config, "max_iterations", "must be at least 1");
  options.tolerance = config.get_or<double>("tolerance", options.tolerance);
  check(options.tolerance >= 0.0, config, "tolerance", "must be non-negative");
  config.reject_unknown();
  return options;
}

}  // namespace tendril::adapt
