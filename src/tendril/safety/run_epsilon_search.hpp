#pragma once

#include <cstdint>
#include <filesystem>

#include "tendril/safety/epsilon_search.hpp"

namespace tendril::safety {

// Algorithm 3 (seed 001 §6.3.2) on a co-training run's safety critic: states are the
// environment's SafetySearchSpace (normalized units), V_safe(s) the critic's state value of the
// observation of s at t = 0, ∇V by central differences (step `gradient_step` in normalized
// units; the SAC critic's V goes through its actor), and an episode is the safety policy's
// greedy rollout from s, whose length counts the steps before the first unsafe state (T_max =
// the environment's horizon when it never enters X_unsafe). Restarts draw s uniformly over the
// safe box (redrawn until V(s) > 0); `seed` seeds the draws and the environment. The CLI moves
// by unit gradients (EpsilonSearchOptions::unit_gradient), α in normalized state units.
struct RunEpsilonSearch {
  EpsilonSearchResult result;
  std::vector<std::string> state_names;
  Eigen::VectorXd state_scales;  // physical units per normalized unit
};
RunEpsilonSearch search_epsilon_of_run(const std::filesystem::path& run_directory,
                                       const EpsilonSearchOptions& options, uint64_t seed,
                                       double gradient_step = 1e-3);

}  // namespace tendril::safety
