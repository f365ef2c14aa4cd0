// Seed 003's ellipse (Sec. VII) and its default levels.
#include "tendril/envs/beam/ellipse_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tendril::envs::beam {
namespace {

TEST(EllipsePath, StartsAtTheTopAndGoesRoundOnce) {
  EllipseSpec spec;
  spec.levels = std::vector<EllipseLevel>{EllipseLevel{{0.25, 0.25}, {0.8, 0.8}, {0.5, 0.5}}};
  EllipsePath ellipse(spec);
  Rng rng(1);
  ellipse.reset(rng);
  const double a = 0.25, b = 0.25 * std::sqrt(1.0 - 0.64);  // 0.15
  EXPECT_NEAR(ellipse.semi_minor_axis(), b, 1e-15);
  EXPECT_EQ(ellipse.position(), Eigen::Vector2d(0.0, 0.70));
  EXPECT_NEAR((ellipse.velocity() - Eigen::Vector2d(a * 0.5, 0.0)).norm(), 0.0, 1e-15);
  const double quarter = std::numbers::pi / 2.0 / 0.5;  // s
  ellipse.advance(rng, quarter);
  EXPECT_NEAR((ellipse.position() - Eigen::Vector2d(a, 0.70 - b)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((ellipse.velocity() - Eigen::Vector2d(0.0, -b * 0.5)).norm(), 0.0, 1e-12);
  ellipse.advance(rng, quarter);
  EXPECT_NEAR((ellipse.position() - Eigen::Vector2d(0.0, 0.70 - 2.0 * b)).norm(), 0.0, 1e-12);
  ellipse.advance(rng, 2.0 * quarter);
  EXPECT_NEAR((ellipse.position() - Eigen::Vector2d(0.0, 0.70)).norm(), 0.0, 1e-12);
  // Every point satisfies (x/a)² + ((y − top + b)/b)² = 1, and v is dx/dt.
  for (int step = 0; step < 100; ++step) {
    const Eigen::Vector2d before = ellipse.position();
    ellipse.advance(rng, 1e-6);
    const Eigen::Vector2d p = ellipse.position();
    EXPECT_NEAR(std::pow(p.x() / a, 2) + std::pow((p.y() - 0.70 + b) / b, 2), 1.0, 1e-12);
    EXPECT_NEAR(((p - before) / 1e-6 - ellipse.velocity()).norm(), 0.0, 1e-6);
    ellipse.advance(rng, 0.1);
  }
}

TEST(EllipsePath, DefaultLevelsGoFromFixedValuesToTheSeedsRanges) {
  const std::vector<EllipseLevel> levels = EllipseSpec{}.levels;
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_EQ(levels[0].semi_major_axis.low, 0.2);
  EXPECT_EQ(levels[0].semi_major_axis.high, 0.2);
  EXPECT_EQ(levels[0].eccentricity.low, 0.6);
  EXPECT_EQ(levels[0].angular_velocity.high, 0.5);
  // ± a quarter of each range's width, clipped: a 0.2 ± 0.0175, e 0.6 ± 0.075, ω [0.5, 0.625].
  EXPECT_NEAR(levels[1].semi_major_axis.low, 0.1825, 1e-15);
  EXPECT_NEAR(levels[1].semi_major_axis.high, 0.2175, 1e-15);
  EXPECT_NEAR(levels[1].eccentricity.low, 0.525, 1e-15);
  EXPECT_NEAR(levels[1].eccentricity.high, 0.675, 1e-15);
  EXPECT_EQ(levels[1].angular_velocity.low, 0.5);
  EXPECT_NEAR(levels[1].angular_velocity.high, 0.625, 1e-15);
  EXPECT_EQ(levels[2].semi_major_axis.low, 0.18);
  EXPECT_EQ(levels[2].semi_major_axis.high, 0.25);
  EXPECT_EQ(levels[2].eccentricity.high, 0.8);
  EXPECT_EQ(levels[2].angular_velocity.high, 1.0);

  EllipsePath ellipse{EllipseSpec{}};
  EXPECT_EQ(ellipse.level(), 2);
  Rng rng(4);
  for (int episode = 0; episode < 50; ++episode) {
    ellipse.reset(rng);
    EXPECT_GE(ellipse.semi_major_axis(), 0.18);
    EXPECT_LE(ellipse.semi_major_axis(), 0.25);
    EXPECT_GE(ellipse.angular_velocity(), 0.5);
    EXPECT_LE(ellipse.angular_velocity(), 1.0);
  }
  ellipse.set_level(0);
  ellipse.reset(rng);
  EXPECT_EQ(ellipse.semi_major_axis(), 0.2);
  EXPECT_NEAR(ellipse.semi_minor_axis(), 0.16, 1e-15);
}

}  // namespace
}  // namespace tendril::envs::beam
