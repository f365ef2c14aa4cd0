// Seed 003's arcs: where the target can be, how it moves, reflects and reverses.
#include "tendril/envs/beam/arc_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs::beam {
namespace {

constexpr double kHalf = 80.0 * std::numbers::pi / 180.0;

TEST(ArcPath, StaysOnItsArcAtItsSpeed) {
  ArcPath arc(ArcSpec{});
  Rng rng(3);
  for (int episode = 0; episode < 20; ++episode) {
    arc.reset(rng);
    ASSERT_GE(arc.radius(), 0.2);
    ASSERT_LE(arc.radius(), 0.6);
    EXPECT_EQ(arc.angular_velocity(), 0.5);
    for (int step = 0; step < 200; ++step) {
      arc.advance(rng, 0.05);
      const Eigen::Vector2d p = arc.position();
      ASSERT_NEAR(p.norm(), arc.radius(), 1e-12);
      ASSERT_LE(std::abs(std::atan2(p.x(), p.y())), kHalf + 1e-12);
      ASSERT_NEAR(arc.velocity().norm(), 0.5 * arc.radius(), 1e-12);
      ASSERT_NEAR(arc.velocity().dot(p), 0.0, 1e-12);  // tangent
    }
  }
}

TEST(ArcPath, VelocityIsTheRateOfChangeOfPosition) {
  ArcSpec spec;
  spec.mean_reversal_interval = 0.0;
  ArcPath arc(spec);
  Rng rng(1);
  arc.set_state(0.4, 0.3, 0.1, 1.0);
  const Eigen::Vector2d before = arc.position();
  arc.advance(rng, 1e-6);
  EXPECT_NEAR(((arc.position() - before) / 1e-6 - arc.velocity()).norm(), 0.0, 1e-6);
  // Direction +1 turns the angle from +y towards +x: clockwise seen from +z.
  EXPECT_GT(arc.velocity().x(), 0.0);
}

TEST(ArcPath, ReflectsAtTheEnds) {
  ArcSpec spec;
  spec.mean_reversal_interval = 0.0;
  ArcPath arc(spec);
  Rng rng(1);
  arc.set_state(0.5, 0.5, kHalf - 0.01, 1.0);
  arc.advance(rng, 0.05);  // 0.025 rad: 0.015 past the end
  EXPECT_NEAR(arc.angle(), kHalf - 0.015, 1e-12);
  EXPECT_EQ(arc.direction(), -1.0);
  arc.set_state(0.5, 0.5, -kHalf + 0.005, -1.0);
  arc.advance(rng, 0.05);
  EXPECT_NEAR(arc.angle(), -kHalf + 0.02, 1e-12);
  EXPECT_EQ(arc.direction(), 1.0);
}

// Flips at rate 1/T: over n steps of dt the expected count is n (1 − e^{−dt/T}); with ω = 0 no
// end is ever reached, so every flip is a random one. 20 000 steps: mean 330, sd 18; ±4 sd.
TEST(ArcPath, ReversesAsAPoissonProcess) {
  ArcSpec spec;
  // Not `levels = {…}`: GCC 12.2 with AVX-512 (-march=native here) miscompiles that assignment
  // into a vector's existing storage, broadcasting the first constant into every field.
  spec.levels = std::vector<ArcLevel>{ArcLevel{{0.4, 0.4}, {0.0, 0.0}}};
  ArcPath arc(spec);
  Rng rng(7);
  arc.reset(rng);
  int flips = 0;
  double direction = arc.direction();
  const int steps = 20000;
  for (int step = 0; step < steps; ++step) {
    arc.advance(rng, 0.05);
    if (arc.direction() != direction) ++flips;
    direction = arc.direction();
  }
  const double expected = steps * -std::expm1(-0.05 / 3.0);
  EXPECT_NEAR(flips, expected, 4.0 * std::sqrt(expected));
}

TEST(ArcPath, LevelsSetTheRangesFromTheNextReset) {
  ArcSpec spec;
  spec.levels =
      std::vector<ArcLevel>{ArcLevel{{0.5, 0.5}, {0.5, 0.5}}, ArcLevel{{0.2, 0.6}, {0.1, 0.5}}};
  ArcPath arc(spec);
  EXPECT_EQ(arc.level(), 1);  // the full task by default
  arc.set_level(0);
  Rng rng(2);
  arc.reset(rng);
  EXPECT_EQ(arc.radius(), 0.5);
  EXPECT_EQ(arc.angular_velocity(), 0.5);
  EXPECT_THROW(arc.set_level(2), Error);
  spec.levels[0].radius = {0.6, 0.2};
  EXPECT_THROW(ArcPath{spec}, Error);
}

}  // namespace
}  // namespace tendril::envs::beam
