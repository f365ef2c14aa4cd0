#include "tendril/adapt/adapt_config.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(AdaptConfig, ReadsEveryGpKey) {
  const Config config = Config::parse(R"(
gp:
  kernel: matern52
  mean_of_targets: false
  window: 500
  restarts: 0
  max_evaluations: 50
  relative_tolerance: 1.0e-6
  length_scale_bounds: [0.01, 10]
  signal_variance_bounds: [0.1, 100]
  noise_variance_bounds: [1.0e-6, 0.5]
)");
  const GpOptions options = read_gp_options(config.child("gp"));
  EXPECT_EQ(options.kernel, KernelType::matern52);
  EXPECT_FALSE(options.mean_of_targets);
  EXPECT_EQ(options.window, 500);
  EXPECT_EQ(options.restarts, 0);
  EXPECT_EQ(options.max_evaluations, 50);
  EXPECT_EQ(options.relative_tolerance, 1e-6);
  EXPECT_EQ(options.min_length_scale, 0.01);
  EXPECT_EQ(options.max_length_scale, 10.0);
  EXPECT_EQ(options.min_signal_variance, 0.1);
  EXPECT_EQ(options.max_signal_variance, 100.0);
  EXPECT_EQ(options.min_noise_variance, 1e-6);
  EXPECT_EQ(options.max_noise_variance, 0.5);
  config.reject_unknown();
}

TEST(AdaptConfig, AbsentKeysKeepTheDefaults) {
  const Config config = Config::parse("gp: {window: 7}");
  GpOptions defaults;
  defaults.kernel = KernelType::matern52;
  const GpOptions options = read_gp_options(config.child("gp"), defaults);
  EXPECT_EQ(options.kernel, KernelType::matern52);
  EXPECT_EQ(options.window, 7);
  EXPECT_EQ(options.restarts, defaults.restarts);
}

TEST(AdaptConfig, ReadsBayesOptAndKMeans) {
  const Config config = Config::parse(R"(
bayes_opt:
  lower: [-0.2, -0.2]
  upper: [0.2, 0.2]
  initial_points: 3
  acquisition: upper_confidence_bound
  confidence: 2.5
  acquisition_candidates: 200
  acquisition_restarts: 3
  seed: 9
  surrogate: {kernel: squared_exponential, restarts: 1}
kmeans: {clusters: 63, init: random, restarts: 10, max_iterations: 300, tolerance: 1.0e-4}
)");
  const BayesOptOptions bo = read_bayes_opt_options(config.child("bayes_opt"));
  EXPECT_EQ(bo.lower, Eigen::Vector2d(-0.2, -0.2));
  EXPECT_EQ(bo.upper, Eigen::Vector2d(0.2, 0.2));
  EXPECT_EQ(bo.initial_points, 3);
  EXPECT_EQ(bo.acquisition, Acquisition::upper_confidence_bound);
  EXPECT_EQ(bo.confidence, 2.5);
  EXPECT_EQ(bo.acquisition_candidates, 200);
  EXPECT_EQ(bo.acquisition_restarts, 3);
  EXPECT_EQ(bo.seed, 9u);
  EXPECT_EQ(bo.surrogate.kernel, KernelType::squared_exponential);
  EXPECT_EQ(bo.surrogate.restarts, 1);
  // Surrogate keys not given keep the surrogate's defaults, not the plain GP's.
  EXPECT_EQ(bo.surrogate.min_length_scale, default_surrogate_options().min_length_scale);
  const KMeansOptions km = read_kmeans_options(config.child("kmeans"));
  EXPECT_EQ(km.clusters, 63);
  EXPECT_EQ(km.init, KMeansInit::random);
  config.reject_unknown();
}

TEST(AdaptConfig, BadKeysAndValuesAreErrorsNamingThem) {
  const auto gp = [](const char* text) {
    return error_message([&] { read_gp_options(Config::parse(text, "exp.yaml").child("gp")); });
  };
  EXPECT_TRUE(contains(gp("gp: {windw: 3}"), "unknown key 'gp.windw'"));
  EXPECT_TRUE(contains(gp("gp: {window: -1}"), "exp.yaml: gp.window: must be non-negative"));
  EXPECT_TRUE(contains(gp("gp: {kernel: rbf}"), "exp.yaml: gp.kernel: unknown kernel 'rbf'"));
  EXPECT_TRUE(contains(gp("gp: {length_scale_bounds: [1, 0.1]}"),
                       "gp.length_scale_bounds: bounds must be positive with min <= max"));
  EXPECT_TRUE(contains(gp("gp: {noise_variance_bounds: [0.1]}"),
                       "gp.noise_variance_bounds: expected [min, max]"));
  EXPECT_TRUE(contains(gp("gp: {restarts: two}"), "gp.restarts"));
  const auto bo = [](const char* text) {
    return error_message(
        [&] { read_bayes_opt_options(Config::parse(text, "exp.yaml").child("bo")); });
  };
  EXPECT_TRUE(contains(bo("bo: {lower: [0, 0], upper: [1]}"), "bo.upper: lower and upper"));
  EXPECT_TRUE(contains(bo("bo: {lower: [0], upper: [1], acquisition: pi}"),
                       "bo.acquisition: unknown acquisition 'pi'"));
  EXPECT_TRUE(contains(bo("bo: {lower: [0], upper: [1], surrogate: {windows: 1}}"),
                       "unknown key 'bo.surrogate.windows'"));
  EXPECT_TRUE(contains(
      error_message([] { read_kmeans_options(Config::parse("km: {clusters: 0}").child("km")); }),
      "km.clusters: must be at least 1"));
}

}  // namespace
}  // namespace tendril::adapt
