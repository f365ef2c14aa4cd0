#pragma once

#include <Eigen/Core>
#include <vector>

#include "tendril/adapt/kmeans.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

struct CoachOptions {
  // Lloyd's runs per module: 10 restarts, 300 iterations, tolerance 1e-4 (seed 002 §IV-B: "10
  // different seeds, randomly chosen initial centroids", scikit-learn's KMeans defaults, whose
  // seeding is k-means++); `clusters` is set per path (L, the mean trajectory length).
  KMeansOptions kmeans{.clusters = 1,
                       .init = KMeansInit::kmeans_plus_plus,
                       .restarts = 10,
                       .max_iterations = 300,
                       .tolerance = 1e-4};
  // Points are clustered as (x, y, z, time_weight · t), t in steps, so that the order in time
  // survives (the seed spec's suggestion): state units per step.
  double time_weight = 5.0;
  // A path row is kept when its module-3 cluster holds points of at least this fraction of the
  // trajectories ("the centroids of clusters whose points have been visited the more often").
  double min_visit_fraction = 0.5;
};

// The coach of BOAC (seed 002 §IV-B): a path of targets x^d_0 … x^d_{L−1} from the oracle's
// deterministic trajectories. Each trajectory (rows: states x_0 … x_T, three coordinates per
// module, the last module's point is the task point) is cut after the first state whose task
// point lies within `radius` of `goal` — the coaching profile's reduced accuracy (15, 10, 5 mm);
// trajectories that never get there are left out. L = the mean length of the cut trajectories.
// Per module, k-means with L clusters (L × 3 in all, the paper's count) over that module's
// points; each module's centroids are ordered by their mean time, row i of the path joins the
// modules' i-th centroids, and rows whose module-3 cluster too few trajectories visit are
// dropped. Raises Error when no trajectory reaches the radius or the states are not triples.
Eigen::MatrixXd coach_path(const std::vector<Eigen::MatrixXd>& trajectories,
                           const Eigen::Vector3d& goal, double radius, const CoachOptions& options,
                           Rng& rng);

}  // namespace tendril::adapt
