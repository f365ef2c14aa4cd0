#include "tendril/adapt/kmeans.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

// Squared distance of every point to every centroid (n × k).
void squared_distances(const Eigen::Ref<const Eigen::MatrixXd>& points,
                       const Eigen::MatrixXd& centroids, Eigen::MatrixXd& out) {
  out.resize(points.rows(), centroids.rows());
  for (Eigen::Index c = 0; c < centroids.rows(); ++c) {
    out.col(c) = (points.rowwise() - centroids.row(c)).rowwise().squaredNorm();
  }
}

// Nearest centroid of every point; returns the inertia.
double assign(const Eigen::MatrixXd& distances, std::vector<int>& labels) {
  double inertia = 0.0;
  for (Eigen::Index i = 0; i < distances.rows(); ++i) {
    Eigen::Index nearest = 0;
    inertia += distances.row(i).minCoeff(&nearest);
    labels[i] = static_cast<int>(nearest);
  }
  return inertia;
}

// Index i with probability weights[i] / Σ weights; uniform when every weight is zero.
Eigen::Index draw_weighted(const Eigen::VectorXd& weights, Rng& rng) {
  const double total = weights.sum();
  if (!(total > 0.0)) return static_cast<Eigen::Index>(rng.below(weights.size()));
  const double target = rng.uniform() * total;
  double cumulative = 0.0;
  for (Eigen::Index i = 0; i < weights.size(); ++i) {
    cumulative += weights[i];
    if (target < cumulative) return i;
  }
  return weights.size() - 1;
}

Eigen::MatrixXd initial_centroids(const Eigen::Ref<const Eigen::MatrixXd>& points, int k,
                                  KMeansInit init, Rng& rng) {
  const auto n = points.rows();
  Eigen::MatrixXd centroids(k, points.cols());
  if (init == KMeansInit::random) {
    // The first k entries of a partial Fisher–Yates shuffle.
    std::vector<Eigen::Index> indices(n);
    std::iota(indices.begin(), indices.end(), 0);
    for (int c = 0; c < k; ++c) {
      std::swap(indices[c], indices[c + rng.below(n - c)]);
      centroids.row(c) = points.row(indices[c]);
    }
    return centroids;
  }
  centroids.row(0) = points.row(static_cast<Eigen::Index>(rng.below(n)));
  Eigen::VectorXd nearest = (points.rowwise() - centroids.row(0)).rowwise().squaredNorm();
  for (int c = 1; c < k; ++c) {
    centroids.row(c) = points.row(draw_weighted(nearest, rng));
    nearest = nearest.cwiseMin((points.rowwise() - centroids.row(c)).rowwise().squaredNorm());
  }
  return centroids;
}

KMeansResult lloyd(const Eigen::Ref<const Eigen::MatrixXd>& points, Eigen::MatrixXd centroids,
                   int max_iterations, double tolerance) {
  const auto n = points.rows();
  const auto k = centroids.rows();
  KMeansResult result;
  result.labels.assign(n, -1);
  std::vector<int> previous(n, -1);
  Eigen::MatrixXd distances, sums(k, points.cols());
  Eigen::VectorXi counts(k);
  for (result.iterations = 1; result.iterations <= max_iterations; ++result.iterations) {
    squared_distances(points, centroids, distances);
    assign(distances, result.labels);
    // Update: each centroid moves to the mean of its points.
    sums.setZero();
    counts.setZero();
    for (Eigen::Index i = 0; i < n; ++i) {
      sums.row(result.labels[i]) += points.row(i);
      ++counts[result.labels[i]];
    }
    Eigen::MatrixXd updated = centroids;
    std::vector<bool> taken(n, false);
    for (Eigen::Index c = 0; c < k; ++c) {
      if (counts[c] > 0) {
        updated.row(c) = sums.row(c) / counts[c];
        continue;
      }
      // Empty: relocate to the point farthest from its own centroid, not yet used for this.
      Eigen::Index farthest = -1;
      double farthest_distance = -1.0;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double d = distances(i, result.labels[i]);
        if (!taken[i] && d > farthest_distance) {
          farthest_distance = d;
          farthest = i;
        }
      }
      taken[farthest] = true;
      updated.row(c) = points.row(farthest);
    }
    const double shift = (updated - centroids).squaredNorm();
    centroids = std::move(updated);
    const bool labels_settled = result.labels == previous;
    previous = result.labels;
    if (labels_settled || shift <= tolerance) {
      result.converged = true;
      break;
    }
  }
  result.iterations = std::min(result.iterations, max_iterations);
  squared_distances(points, centroids, distances);
  result.inertia = assign(distances, result.labels);
  result.centroids = std::move(centroids);
  result.counts.assign(k, 0);
  for (int label : result.labels) ++result.counts[label];
  return result;
}

}  // namespace

KMeansInit kmeans_init_from_name(std::string_view name, std::string_view where) {
  if (name == "kmeans++") return KMeansInit::kmeans_plus_plus;
  if (name == "random") return KMeansInit::random;
  throw Error(
      "unknown k-means initialisation '" + std::string(name) + "' (expected kmeans++ or random)",
      std::string(where));
}

std::string kmeans_init_name(KMeansInit init) {
  return init == KMeansInit::kmeans_plus_plus ? "kmeans++" : "random";
}

KMeansResult kmeans(const Eigen::Ref<const Eigen::MatrixXd>& points, const KMeansOptions& options,
                    Rng& rng) {
  const std::string where = "kmeans";
  if (options.clusters < 1) {
    throw Error("clusters is " + std::to_string(options.clusters) + " (must be at least 1)", where);
  }
  if (points.rows() < options.clusters) {
    throw Error(std::to_string(options.clusters) + " clusters need at least as many points (got " +
                    std::to_string(points.rows()) + ")",
                where);
  }
  require(points.cols() > 0, "points have no dimensions", where);
  require(options.restarts >= 1 && options.max_iterations >= 1,
          "restarts and max_iterations must be at least 1", where);
  require(options.tolerance >= 0.0, "tolerance must be non-negative", where);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (!points.row(i).allFinite()) {
      throw Error("point " + std::to_string(i) + " is not finite", where);
    }
  }
  const Eigen::RowVectorXd mean = points.colwise().mean();
  const double mean_variance = (points.rowwise() - mean).array().square().colwise().mean().mean();
  const double tolerance = options.tolerance * mean_variance;

  KMeansResult best;
  best.inertia = std::numeric_limits<double>::infinity();
  for (int run = 0; run < options.restarts; ++run) {
    KMeansResult result =
        lloyd(points, initial_centroids(points, options.clusters, options.init, rng),
              options.max_iterations, tolerance);
    if (result.inertia < best.inertia) best = std::move(result);
  }
  return best;
}

}  // namespace tendril::adapt
