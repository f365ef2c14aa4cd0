#pragma once

#include "tendril/adapt/bayesian_optimizer.hpp"
#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/adapt/kmeans.hpp"
#include "tendril/core/config.hpp"

namespace tendril::adapt {

// Readers of the adaptation options from an experiment's YAML. Every key is optional (the
// given defaults stand); an unknown key, a value of the wrong type or out of range is an
// Error naming its key.
//
//   gp:        kernel (squared_exponential | matern52), mean_of_targets, window, restarts,
//              max_evaluations, relative_tolerance, length_scale_bounds [min, max],
//              signal_variance_bounds [min, max], noise_variance_bounds [min, max]
//   bayes_opt: lower, upper (lists), initial_points, acquisition (expected_improvement |
//              upper_confidence_bound), exploration, confidence, acquisition_candidates,
//              acquisition_restarts, seed, surrogate (a gp mapping)
//   kmeans:    clusters, init (kmeans++ | random), restarts, max_iterations, tolerance
GpOptions read_gp_options(const Config& config, GpOptions defaults = {});
BayesOptOptions read_bayes_opt_options(const Config& config, BayesOptOptions defaults = {});
KMeansOptions read_kmeans_options(const Config& config, KMeansOptions defaults = {});

}  // namespace tendril::adapt
