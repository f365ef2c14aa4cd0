#include "tendril/adapt/kmeans.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "support/error_message.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

struct Planted {
  Eigen::MatrixXd points;
  Eigen::MatrixXd centres;
  std::vector<int> truth;
};

// Four isotropic Gaussian blobs (σ = 0.3) around centres 4 apart or more, in 3-D, of unequal
// sizes.
Planted planted_clusters(uint64_t seed) {
  Planted p;
  p.centres.resize(4, 3);
  p.centres << 0, 0, 0, 4, 0, 0, 0, 5, 1, 3, 4, -4;
  const int sizes[4] = {40, 25, 60, 35};
  Rng rng(seed);
  p.points.resize(160, 3);
  int row = 0;
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i < sizes[c]; ++i, ++row) {
      for (int j = 0; j < 3; ++j) p.points(row, j) = p.centres(c, j) + 0.3 * rng.normal();
      p.truth.push_back(c);
    }
  }
  return p;
}

TEST(KMeans, RecoversPlantedClusters) {
  for (KMeansInit init : {KMeansInit::kmeans_plus_plus, KMeansInit::random}) {
    const Planted planted = planted_clusters(1);
    KMeansOptions options;
    options.clusters = 4;
    options.init = init;
    Rng rng(2);
    const KMeansResult result = kmeans(planted.points, options, rng);
    ASSERT_EQ(result.centroids.rows(), 4);
    EXPECT_TRUE(result.converged);
    // Every planted centre has a centroid within 0.15 (the standard error of a blob's mean is
    // 0.3/√25 = 0.06 per coordinate), and each blob maps to exactly one label.
    std::set<int> labels_used;
    for (int c = 0; c < 4; ++c) {
      Eigen::Index nearest = 0;
      const double distance =
          (result.centroids.rowwise() - planted.centres.row(c)).rowwise().norm().minCoeff(&nearest);
      EXPECT_LT(distance, 0.15) << kmeans_init_name(init) << " centre " << c;
      labels_used.insert(static_cast<int>(nearest));
      for (size_t i = 0; i < planted.truth.size(); ++i) {
        if (planted.truth[i] == c) {
          ASSERT_EQ(result.labels[i], nearest) << "point " << i;
        }
      }
      EXPECT_EQ(result.counts[nearest], std::count(planted.truth.begin(), planted.truth.end(), c));
    }
    EXPECT_EQ(labels_used.size(), 4u);
  }
}

TEST(KMeans, HandComputedOneDimensionalCase) {
  Eigen::MatrixXd points(5, 1);
  points << 0.0, 1.0, 2.0, 10.0, 12.0;
  KMeansOptions options;
  options.clusters = 2;
  Rng rng(3);
  const KMeansResult result = kmeans(points, options, rng);
  const double low = std::min(result.centroids(0, 0), result.centroids(1, 0));
  const double high = std::max(result.centroids(0, 0), result.centroids(1, 0));
  EXPECT_DOUBLE_EQ(low, 1.0);
  EXPECT_DOUBLE_EQ(high, 11.0);
  EXPECT_DOUBLE_EQ(result.inertia, 1.0 + 0.0 + 1.0 + 1.0 + 1.0);
}

TEST(KMeans, ResultIsALloydFixedPoint) {
  const Planted planted = planted_clusters(4);
  KMeansOptions options;
  options.clusters = 6;  // more clusters than blobs: a less trivial optimum
  options.tolerance = 0.0;
  Rng rng(5);
  const KMeansResult result = kmeans(planted.points, options, rng);
  EXPECT_TRUE(result.converged);
  double inertia = 0.0;
  for (int c = 0; c < 6; ++c) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    int count = 0;
    for (int i = 0; i < planted.points.rows(); ++i) {
      const Eigen::RowVector3d point = planted.points.row(i);
      if (result.labels[i] == c) {
        sum += point;
        ++count;
        inertia += (point - result.centroids.row(c)).squaredNorm();
      }
      // Each point is at its nearest centroid.
      const double own = (point - result.centroids.row(result.labels[i])).squaredNorm();
      ASSERT_LE(own, (point - result.centroids.row(c)).squaredNorm() + 1e-12);
    }
    ASSERT_GT(count, 0);
    EXPECT_LT((sum / count - result.centroids.row(c)).norm(), 1e-12);  // the mean of its points
  }
  EXPECT_NEAR(result.inertia, inertia, 1e-9);
}

TEST(KMeans, RestartsKeepTheLowestInertia) {
  const Planted planted = planted_clusters(6);
  KMeansOptions one;
  one.clusters = 7;
  one.restarts = 1;
  one.init = KMeansInit::random;
  KMeansOptions ten = one;
  ten.restarts = 10;
  Rng rng_one(7), rng_ten(7);
  // The first of the ten runs draws what the single run draws, so the best of ten is no worse.
  const double single = kmeans(planted.points, one, rng_one).inertia;
  const double best = kmeans(planted.points, ten, rng_ten).inertia;
  EXPECT_LE(best, single);
}

TEST(KMeans, IterationAndToleranceLimitsStopEarly) {
  const Planted planted = planted_clusters(8);
  KMeansOptions options;
  options.clusters = 12;
  options.restarts = 1;
  options.init = KMeansInit::random;
  options.tolerance = 0.0;
  Rng rng_exact(9), rng_capped(9), rng_loose(9);
  const KMeansResult exact = kmeans(planted.points, options, rng_exact);
  ASSERT_GT(exact.iterations, 2);
  options.max_iterations = 2;
  const KMeansResult capped = kmeans(planted.points, options, rng_capped);
  EXPECT_EQ(capped.iterations, 2);
  EXPECT_FALSE(capped.converged);
  options.max_iterations = 300;
  options.tolerance = 10.0;  // centroids may still move by 10 × the mean variance
  const KMeansResult loose = kmeans(planted.points, options, rng_loose);
  EXPECT_TRUE(loose.converged);
  EXPECT_LT(loose.iterations, exact.iterations);
}

TEST(KMeans, SameSeedSameResult) {
  const Planted planted = planted_clusters(10);
  KMeansOptions options;
  options.clusters = 5;
  Rng first(11), second(11);
  const KMeansResult a = kmeans(planted.points, options, first);
  const KMeansResult b = kmeans(planted.points, options, second);
  EXPECT_EQ(a.centroids, b.centroids);
  EXPECT_EQ(a.labels, b.labels);
  EXPECT_EQ(first.state(), second.state());
}

TEST(KMeans, MoreClustersThanDistinctPointsStillGivesValidCentroids) {
  Eigen::MatrixXd points = Eigen::MatrixXd::Zero(10, 2);
  points.row(9) << 5.0, 5.0;
  KMeansOptions options;
  options.clusters = 3;
  Rng rng(12);
  const KMeansResult result = kmeans(points, options, rng);
  EXPECT_TRUE(result.centroids.allFinite());
  EXPECT_EQ(result.inertia, 0.0);
}

TEST(KMeans, BadInputIsAnErrorNamingIt) {
  Rng rng(0);
  KMeansOptions options;
  options.clusters = 3;
  Eigen::MatrixXd points = Eigen::MatrixXd::Zero(5, 2);
  points(3, 1) = NAN;
  EXPECT_NE(error_message([&] { kmeans(points, options, rng); }).find("point 3 is not finite"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              kmeans(Eigen::MatrixXd::Zero(2, 2), options, rng);
            }).find("3 clusters need at least as many points (got 2)"),
            std::string::npos);
  options.clusters = 0;
  EXPECT_NE(error_message([&] {
              kmeans(Eigen::MatrixXd::Zero(2, 2), options, rng);
            }).find("clusters is 0"),
            std::string::npos);
  EXPECT_NE(error_message([] {
              kmeans_init_from_name("k-means++", "coach.init");
            }).find("coach.init: unknown k-means initialisation 'k-means++'"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::adapt
