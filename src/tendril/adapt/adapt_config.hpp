#pragma once

#include "tendril/adapt/bayesian_optimizer.hpp"
#include "tendril/adapt/boac.hpp"
#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/adapt/gprca_trials.hpp"
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
//   gprca:     max_trials, steps_per_trial (a number; the caller reads a per-scenario map),
//              trials_after_goal, search_between_trials, input (command | delta),
//              retrain_every, search_every, search_below, sharing (per_output | shared), seed,
//              gp (a gp mapping)
//   boac:      oracle (closed_loop | open_loop), oracle_trials, best_trials, oracle_steps,
//   coach_episodes, profiles_mm,
//              local_flag_mm, batch, hold_steps, max_trials_per_profile, max_trials,
//              offset_bound_mm, collision_penalty_mm, sharing, time_weight_mm_per_step,
//              min_visit_fraction, kmeans, student (a gp mapping), bayes_opt (without bounds)
GpOptions read_gp_options(const Config& config, GpOptions defaults = {});
BayesOptOptions read_bayes_opt_options(const Config& config, BayesOptOptions defaults = {});
KMeansOptions read_kmeans_options(const Config& config, KMeansOptions defaults = {});
// `steps_per_trial` is left to the caller (it may be a per-scenario mapping): skipped here.
GprcaTrialsOptions read_gprca_trials_options(const Config& config,
                                             GprcaTrialsOptions defaults = {});
BoacOptions read_boac_options(const Config& config, BoacOptions defaults = {});

}  // namespace tendril::adapt
