#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// How the first centroids are chosen:
//   kmeans_plus_plus  one point uniformly, then each next with probability ∝ its squared
//                     distance to the nearest centroid chosen so far (Arthur & Vassilvitskii
//                     2007, "k-means++: the advantages of careful seeding")
//   random            `clusters` distinct points uniformly
enum class KMeansInit { kmeans_plus_plus, random };

// "kmeans++" or "random"; anything else raises Error naming `where`.
KMeansInit kmeans_init_from_name(std::string_view name, std::string_view where = {});
std::string kmeans_init_name(KMeansInit init);

// Defaults are scikit-learn's KMeans (n_init 10, max_iter 300, tol 1e-4), which seed 002's coach
// uses.
struct KMeansOptions {
  int clusters = 8;
  KMeansInit init = KMeansInit::kmeans_plus_plus;
  int restarts = 10;         // independent runs; the lowest inertia wins
  int max_iterations = 300;  // Lloyd iterations per run
  // A run stops when the centroids moved by Σ‖Δc‖² ≤ tolerance × (mean over dimensions of the
  // points' variance) — scikit-learn's relative tolerance — or when no label changed.
  double tolerance = 1e-4;
};

struct KMeansResult {
  Eigen::MatrixXd centroids;  // clusters × dim
  std::vector<int> labels;    // the nearest centroid of every point
  std::vector<int> counts;    // points per cluster
  double inertia = 0.0;       // Σ squared distance of each point to its centroid
  int iterations = 0;         // Lloyd iterations of the winning run
  bool converged = false;     // whether that run stopped before max_iterations
};

// Lloyd's algorithm (Lloyd 1982) on the rows of `points` (n × dim). A cluster left empty takes
// the point farthest from its centroid. Labels and inertia are those of the final centroids.
// Same points, options and generator state → same result.
KMeansResult kmeans(const Eigen::Ref<const Eigen::MatrixXd>& points, const KMeansOptions& options,
                    Rng& rng);

}  // namespace tendril::adapt
