#include "tendril/envs/elastica/target_motion.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::envs::elastica {
namespace {

bool inside(const Eigen::Vector3d& x, const TargetMotion::Params& box) {
  return (x.array() >= box.box_low.array()).all() && (x.array() <= box.box_high.array()).all();
}

// SPEC M2 case 1: 0.5 m/s, a new direction every 500 RL steps, reflection at the box walls.
TEST(TargetMotion, StaysInTheBoxAtConstantSpeedOverAHundredThousandUpdates) {
  TargetMotion motion;
  const TargetMotion::Params& p = motion.params();
  Rng rng(42);
  motion.reset(rng);
  ASSERT_TRUE(inside(motion.position(), p));
  Eigen::Vector3d lowest = motion.position(), highest = motion.position();
  int direction_changes = 0, reflections = 0;
  for (long update = 0; update < 100000; ++update) {
    const Eigen::Vector3d before = motion.velocity();
    motion.advance(rng);
    ASSERT_TRUE(inside(motion.position(), p))
        << "update " << update << ": " << motion.position().transpose();
    ASSERT_NEAR(motion.velocity().norm(), 0.5, 1e-12);
    const Eigen::Vector3d after = motion.velocity();
    if (update % 500 == 0 && update > 0) {
      // A fresh direction: at least one component changes magnitude.
      ASSERT_GT((after.cwiseAbs() - before.cwiseAbs()).norm(), 0.0) << update;
      ++direction_changes;
    } else {
      // Otherwise only reflections: components keep their magnitude, some may flip sign.
      ASSERT_EQ(after.cwiseAbs(), before.cwiseAbs()) << update;
      if (after != before) ++reflections;
    }
    lowest = lowest.cwiseMin(motion.position());
    highest = highest.cwiseMax(motion.position());
  }
  EXPECT_EQ(direction_changes, 199);
  EXPECT_GT(reflections, 50);
  // The walk explores the whole box: it comes within 2 cm of all six walls.
  EXPECT_LT((lowest - p.box_low).maxCoeff(), 0.02);
  EXPECT_LT((p.box_high - highest).maxCoeff(), 0.02);
}

TEST(TargetMotion, MovesSpeedTimesStepAndMirrorsAtAWall) {
  TargetMotion motion;
  Rng rng(1);
  motion.set_state(Eigen::Vector3d(0.0, 0.5, 0.0), Eigen::Vector3d(0.3, 0.0, -0.4));
  motion.advance(rng);
  EXPECT_TRUE(motion.position().isApprox(Eigen::Vector3d(0.3 * 1.4e-3, 0.5, -0.4 * 1.4e-3)));

  // 0.2 mm short of the x = 0.6 wall, moving +x at 0.5 m/s: 0.7 mm later it is 0.5 mm back.
  motion.set_state(Eigen::Vector3d(0.5998, 0.5, 0.0), Eigen::Vector3d(0.5, 0.0, 0.0));
  motion.advance(rng);
  EXPECT_NEAR(motion.position().x(), 0.6 - 0.0005, 1e-12);
  EXPECT_EQ(motion.velocity(), Eigen::Vector3d(-0.5, 0.0, 0.0));
  // The floor y = 0.3 likewise.
  motion.set_state(Eigen::Vector3d(0.0, 0.3001, 0.0), Eigen::Vector3d(0.0, -0.5, 0.0));
  motion.advance(rng);
  EXPECT_NEAR(motion.position().y(), 0.3 + 0.0006, 1e-12);
  EXPECT_EQ(motion.velocity(), Eigen::Vector3d(0.0, 0.5, 0.0));
}

TEST(TargetMotion, AHeldTargetOutsideTheBoxStaysPut) {
  TargetMotion motion;
  Rng rng(1);
  motion.set_state(Eigen::Vector3d(0.0, 1.0, 0.0), Eigen::Vector3d::Zero());
  for (int i = 0; i < 10; ++i) motion.advance(rng);
  EXPECT_EQ(motion.position(), Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_THROW(motion.set_state(Eigen::Vector3d(0.0, NAN, 0.0), Eigen::Vector3d::Zero()), Error);
}

TEST(TargetMotion, ResetIsUniformInTheBoxAndSeeded) {
  TargetMotion motion;
  const TargetMotion::Params& box = motion.params();
  Rng rng(9);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), second = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_direction = Eigen::Vector3d::Zero(),
                  direction_second = Eigen::Vector3d::Zero();
  Eigen::Vector3d lowest = box.box_high, highest = box.box_low;
  std::array<int, 8> octants{};
  const Eigen::Vector3d centre = 0.5 * (box.box_low + box.box_high);
  const int draws = 20000;
  for (int i = 0; i < draws; ++i) {
    motion.reset(rng);
    const Eigen::Vector3d& x = motion.position();
    ASSERT_TRUE(inside(x, box));
    ASSERT_NEAR(motion.velocity().norm(), 0.5, 1e-12);
    ASSERT_EQ(motion.updates(), 0);
    mean += x / draws;
    second += x.cwiseProduct(x) / draws;
    lowest = lowest.cwiseMin(x);
    highest = highest.cwiseMax(x);
    octants[(x.x() > centre.x()) + 2 * (x.y() > centre.y()) + 4 * (x.z() > centre.z())] += 1;
    const Eigen::Vector3d direction = motion.velocity() / 0.5;
    mean_direction += direction / draws;
    direction_second += direction.cwiseProduct(direction) / draws;
  }
  // Centre (0, 0.6, 0); the standard error of each mean is below 0.003.
  EXPECT_LT((mean - centre).cwiseAbs().maxCoeff(), 0.015);
  // U(a, b) has variance (b − a)²/12; the relative standard error of the sample variance is
  // √(0.8/n) ≈ 0.6 %, so 4 % is over six of them.
  const Eigen::Vector3d variance = second - mean.cwiseProduct(mean);
  const Eigen::Vector3d expected = (box.box_high - box.box_low).array().square() / 12.0;
  EXPECT_LT((variance.array() / expected.array() - 1.0).abs().maxCoeff(), 0.04)
      << variance.transpose() << " vs " << expected.transpose();
  // The draws reach all six walls (within 0.5 % of the span).
  EXPECT_LT(((lowest - box.box_low).array() / (box.box_high - box.box_low).array()).maxCoeff(),
            0.005);
  EXPECT_LT(((box.box_high - highest).array() / (box.box_high - box.box_low).array()).maxCoeff(),
            0.005);
  // χ² over the eight octants (7 degrees of freedom; P(χ² > 30) ≈ 10⁻⁴).
  double chi_square = 0.0;
  for (int count : octants) chi_square += std::pow(count - draws / 8.0, 2) / (draws / 8.0);
  EXPECT_LT(chi_square, 30.0);
  // Directions uniform on the sphere: each component is uniform on [−1, 1] (Archimedes), mean 0
  // and second moment 1/3 (standard error 0.002).
  EXPECT_LT(mean_direction.cwiseAbs().maxCoeff(), 0.03);
  EXPECT_LT((direction_second.array() - 1.0 / 3.0).abs().maxCoeff(), 0.012)
      << direction_second.transpose();

  TargetMotion a, b;
  Rng rng_a(5), rng_b(5);
  a.reset(rng_a);
  b.reset(rng_b);
  for (int i = 0; i < 1200; ++i) {
    a.advance(rng_a);
    b.advance(rng_b);
  }
  EXPECT_EQ(a.position(), b.position());
  EXPECT_EQ(a.velocity(), b.velocity());
}

TEST(TargetMotion, RejectsAnEmptyBox) {
  TargetMotion::Params params;
  params.box_high.y() = params.box_low.y();
  EXPECT_THROW(TargetMotion{params}, Error);
  params = {};
  params.steps_per_direction = 0;
  EXPECT_THROW(TargetMotion{params}, Error);
}

}  // namespace
}  // namespace tendril::envs::elastica
