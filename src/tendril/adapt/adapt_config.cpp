#include "tendril/adapt/adapt_config.hpp"

#include <cmath>
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

namespace {

HyperparameterSharing read_sharing(const Config& config, HyperparameterSharing fallback) {
  if (!config.has("sharing")) return fallback;
  const auto name = config.get<std::string>("sharing");
  if (name == "per_output") return HyperparameterSharing::per_output;
  if (name == "shared") return HyperparameterSharing::shared;
  throw Error("unknown sharing '" + name + "' (expected per_output or shared)",
              where(config, "sharing"));
}

int read_count(const Config& config, const char* key, int fallback, int minimum) {
  const int value = config.get_or<int>(key, fallback);
  check(value >= minimum, config, key,
        minimum == 0 ? "must be non-negative" : "must be at least 1");
  return value;
}

double read_positive(const Config& config, const char* key, double fallback) {
  const double value = config.get_or<double>(key, fallback);
  check(std::isfinite(value) && value > 0.0, config, key, "must be finite and positive");
  return value;
}

}  // namespace

GprcaTrialsOptions read_gprca_trials_options(const Config& config, GprcaTrialsOptions defaults) {
  GprcaTrialsOptions options = defaults;
  options.max_trials = read_count(config, "max_trials", options.max_trials, 1);
  options.trials_after_goal = read_count(config, "trials_after_goal", options.trials_after_goal, 0);
  options.search_between_trials =
      config.get_or<bool>("search_between_trials", options.search_between_trials);
  if (config.has("input")) {
    const auto name = config.get<std::string>("input");
    if (name == "command") {
      options.input = CompensatorInput::command;
    } else if (name == "delta") {
      options.input = CompensatorInput::delta;
    } else {
      throw Error("unknown input '" + name + "' (expected command or delta)",
                  where(config, "input"));
    }
  }
  CompensationOptions& compensator = options.compensator;
  compensator.retrain_every = read_count(config, "retrain_every", compensator.retrain_every, 1);
  compensator.search_every = read_count(config, "search_every", compensator.search_every, 0);
  compensator.search_below = read_count(config, "search_below", compensator.search_below, 0);
  compensator.sharing = read_sharing(config, compensator.sharing);
  compensator.seed = config.get_or<uint64_t>("seed", compensator.seed);
  if (config.has("gp")) compensator.gp = read_gp_options(config.child("gp"), compensator.gp);
  return options;  // steps_per_trial: the caller's, then reject_unknown
}

BoacOptions read_boac_options(const Config& config, BoacOptions defaults) {
  BoacOptions options = defaults;
  if (config.has("oracle")) {
    const auto name = config.get<std::string>("oracle");
    check(name == "closed_loop" || name == "open_loop", config, "oracle",
          "must be closed_loop or open_loop");
    options.oracle_open_loop = name == "open_loop";
  }
  options.oracle_trials = read_count(config, "oracle_trials", options.oracle_trials, 1);
  options.best_trials = read_count(config, "best_trials", options.best_trials, 1);
  check(options.best_trials <= options.oracle_trials, config, "best_trials",
        "must not exceed oracle_trials");
  options.oracle_steps = read_count(config, "oracle_steps", options.oracle_steps, 1);
  options.coach_episodes = read_count(config, "coach_episodes", options.coach_episodes, 1);
  if (config.has("profiles_mm")) {
    options.profiles = config.get<std::vector<double>>("profiles_mm");
    check(!options.profiles.empty(), config, "profiles_mm", "needs at least one radius");
    for (double radius : options.profiles) {
      check(std::isfinite(radius) && radius > 0.0, config, "profiles_mm",
            "radii must be finite and positive");
    }
  }
  options.local_flag = read_positive(config, "local_flag_mm", options.local_flag);
  options.batch = read_count(config, "batch", options.batch, 1);
  options.hold_steps = read_count(config, "hold_steps", options.hold_steps, 0);
  options.max_trials_per_profile =
      read_count(config, "max_trials_per_profile", options.max_trials_per_profile, 1);
  options.max_trials = read_count(config, "max_trials", options.max_trials, 1);
  options.offset_bound = read_positive(config, "offset_bound_mm", options.offset_bound);
  options.collision_penalty =
      config.get_or<double>("collision_penalty_mm", options.collision_penalty);
  check(options.collision_penalty >= 0.0, config, "collision_penalty_mm", "must be non-negative");
  options.sharing = read_sharing(config, options.sharing);
  options.coach.time_weight =
      config.get_or<double>("time_weight_mm_per_step", options.coach.time_weight);
  check(options.coach.time_weight >= 0.0, config, "time_weight_mm_per_step",
        "must be non-negative");
  options.coach.min_visit_fraction =
      config.get_or<double>("min_visit_fraction", options.coach.min_visit_fraction);
  check(options.coach.min_visit_fraction >= 0.0 && options.coach.min_visit_fraction <= 1.0, config,
        "min_visit_fraction", "must lie in [0, 1]");
  if (config.has("kmeans")) {
    options.coach.kmeans = read_kmeans_options(config.child("kmeans"), options.coach.kmeans);
  }
  if (config.has("student"))
    options.student = read_gp_options(config.child("student"), options.student);
  if (config.has("bayes_opt")) {
    BayesOptOptions bounded = options.bayes_opt;
    bounded.lower = Eigen::VectorXd::Constant(3, -options.offset_bound);
    bounded.upper = Eigen::VectorXd::Constant(3, options.offset_bound);
    const Config bayes_opt = config.child("bayes_opt");
    check(!bayes_opt.has("lower") && !bayes_opt.has("upper"), config, "bayes_opt",
          "takes its bounds from offset_bound_mm, not lower/upper");
    options.bayes_opt = read_bayes_opt_options(bayes_opt, bounded);
  }
  config.reject_unknown();
  return options;
}

}  // namespace tendril::adapt
