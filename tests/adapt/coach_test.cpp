#include "tendril/adapt/coach.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

const Eigen::Vector3d kStart{0.0, 0.0, -600.0};
const Eigen::Vector3d kGoal{-30.0, -120.0, -620.0};

// Noisy copies of the straight path start → goal in 12 steps (13 states), one module.
std::vector<Eigen::MatrixXd> demonstrations(int count, uint64_t seed) {
  Rng rng(seed);
  std::vector<Eigen::MatrixXd> trajectories;
  for (int n = 0; n < count; ++n) {
    Eigen::MatrixXd states(13, 3);
    for (int t = 0; t <= 12; ++t) {
      const Eigen::Vector3d point = kStart + (t / 12.0) * (kGoal - kStart);
      for (int i = 0; i < 3; ++i) states(t, i) = point[i] + 0.5 * rng.normal();
    }
    trajectories.push_back(states);
  }
  return trajectories;
}

TEST(Coach, ThePathRunsInTimeOrderAndEndsWithinTheProfile) {
  const auto trajectories = demonstrations(8, 1);
  // One step moves 10.44 mm: within 15 mm of the goal from step 11, within 7 or 5 mm only at
  // step 12: the 15 mm profile cuts at 12 states, the others keep all 13.
  for (const double radius : {15.0, 7.0, 5.0}) {
    Rng rng(2);
    const Eigen::MatrixXd path = coach_path(trajectories, kGoal, radius, CoachOptions{}, rng);
    const int expected_rows = radius > 12.0 ? 12 : 13;
    ASSERT_EQ(path.rows(), expected_rows) << radius;
    EXPECT_LT((path.row(0).transpose() - kStart).norm(), 1.0);
    for (Eigen::Index i = 1; i < path.rows(); ++i) {
      // Each target lies one step further along the line than the one before.
      const double before = (path.row(i - 1).transpose() - kGoal).norm();
      const double after = (path.row(i).transpose() - kGoal).norm();
      EXPECT_NEAR(before - after, (kGoal - kStart).norm() / 12.0, 1.0) << radius << " " << i;
    }
    EXPECT_LE((path.bottomRows<1>().transpose() - kGoal).norm(), radius) << radius;
  }
}

TEST(Coach, ModulesAreClusteredApartAndRarePointsAreDropped) {
  // Two modules: module 1 still, module 2 the line; the coach's rows pair them by time. One
  // trajectory wanders 300 mm off at its middle: its cluster is visited by 1 of 9 and dropped.
  std::vector<Eigen::MatrixXd> trajectories;
  for (const Eigen::MatrixXd& line : demonstrations(8, 3)) {
    Eigen::MatrixXd states(line.rows(), 6);
    states.leftCols<3>().rowwise() = Eigen::RowVector3d(1.0, 2.0, -200.0);
    states.rightCols<3>() = line;
    trajectories.push_back(states);
  }
  Eigen::MatrixXd wanderer = trajectories.front();
  wanderer(6, 3) += 300.0;
  trajectories.push_back(wanderer);
  Rng rng(4);
  CoachOptions options;
  const Eigen::MatrixXd path = coach_path(trajectories, kGoal, 5.0, options, rng);
  for (Eigen::Index i = 0; i < path.rows(); ++i) {
    EXPECT_LT((path.row(i).head<3>() - Eigen::RowVector3d(1.0, 2.0, -200.0)).norm(), 1e-9);
    EXPECT_LT(path(i, 3), 50.0) << "the wanderer's point was kept";
  }
  options.min_visit_fraction = 0.0;
  Rng again(4);
  const Eigen::MatrixXd all = coach_path(trajectories, kGoal, 5.0, options, again);
  EXPECT_EQ(all.rows(), path.rows() + 1);
}

TEST(Coach, SameSeedSamePathAndBadInputIsNamed) {
  const auto trajectories = demonstrations(5, 7);
  Rng a(9), b(9);
  EXPECT_EQ(coach_path(trajectories, kGoal, 10.0, CoachOptions{}, a),
            coach_path(trajectories, kGoal, 10.0, CoachOptions{}, b));
  Rng rng(1);
  EXPECT_NE(error_message([&] {
              coach_path(trajectories, Eigen::Vector3d(500, 0, 0), 10.0, CoachOptions{}, rng);
            }).find("no trajectory comes within 10"),
            std::string::npos);
  EXPECT_THROW(coach_path({Eigen::MatrixXd::Zero(4, 4)}, kGoal, 10.0, CoachOptions{}, rng), Error);
  EXPECT_THROW(coach_path(trajectories, kGoal, -1.0, CoachOptions{}, rng), Error);
}

}  // namespace
}  // namespace tendril::adapt
