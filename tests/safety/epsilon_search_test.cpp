#include "tendril/safety/epsilon_search.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tendril::safety {
namespace {

// A scripted 1-D problem: V(x) = 10 x, and the safety policy survives T_max = 50 steps from x
// exactly when x ≥ 0.27 (the true boundary, V = 2.7), failing after 7 steps otherwise.
EpsilonSearchProblem scripted_problem() {
  EpsilonSearchProblem problem;
  problem.value = [](const Eigen::VectorXd& x) { return 10.0 * x[0]; };
  problem.gradient = [](const Eigen::VectorXd&) { return Eigen::VectorXd::Constant(1, 10.0); };
  problem.episode_length = [](const Eigen::VectorXd& x) -> int64_t {
    return x[0] >= 0.27 ? 50 : 7;
  };
  problem.max_episode_length = 50;
  return problem;
}

TEST(EpsilonSearch, HalvesTheStepWhenTheOutcomeFlipsAndMovesAlongTheGradient) {
  const EpsilonSearchProblem problem = scripted_problem();
  EpsilonSearchOptions options;
  options.step_size = 0.02;
  options.tolerance = 0.05;
  const EpsilonSearchRun run =
      search_epsilon_once(problem, options, Eigen::VectorXd::Constant(1, 1.0));
  ASSERT_TRUE(run.converged);
  ASSERT_GE(run.trace.size(), 3u);
  // l_prev starts at −∞: the first survival halves α.
  EXPECT_DOUBLE_EQ(run.trace[0].step_size, 0.01);
  int flips = 0;
  for (size_t k = 0; k < run.trace.size(); ++k) {
    const bool survived = run.trace[k].episode_length == 50;
    EXPECT_EQ(survived, run.trace[k].state[0] >= 0.27);
    if (k > 0) {
      const bool survived_before = run.trace[k - 1].episode_length == 50;
      const double ratio = run.trace[k].step_size / run.trace[k - 1].step_size;
      EXPECT_DOUBLE_EQ(ratio, survived != survived_before ? 0.5 : 1.0) << k;
      flips += survived != survived_before ? 1 : 0;
    }
    // Survived: down the gradient (x − α ∇V); failed: up.
    const double next = k + 1 < run.trace.size() ? run.trace[k + 1].state[0] : -1.0;
    if (k + 1 < run.trace.size()) {
      EXPECT_NEAR(next - run.trace[k].state[0], (survived ? -10.0 : 10.0) * run.trace[k].step_size,
                  1e-12);
    }
  }
  EXPECT_GE(flips, 3);
  // Stopped when |ΔV| = 10 α · 10 ≤ δ, at most one step from the boundary.
  const double last_alpha = run.trace.back().step_size;
  EXPECT_LE(100.0 * last_alpha, options.tolerance);
  EXPECT_NEAR(run.epsilon, 2.7, 100.0 * last_alpha * 2.0 + 1e-9);
}

// One search from x = 1 with unit-gradient steps (α₀ = 0.2, δ = 0.05).
EpsilonSearchRun unit_gradient_search(bool survivor_value) {
  EpsilonSearchOptions options;
  options.step_size = 0.2;
  options.tolerance = 0.05;
  options.unit_gradient = true;
  options.survivor_value = survivor_value;
  return search_epsilon_once(scripted_problem(), options, Eigen::VectorXd::Constant(1, 1.0));
}

// With unit_gradient each move is ±α along ∇V's direction: the search bisects the boundary in
// state units whatever V's scale (here ∇V = 10).
TEST(EpsilonSearch, UnitGradientStepsMoveByTheStepSize) {
  const EpsilonSearchRun run = unit_gradient_search(/*survivor_value=*/false);
  ASSERT_TRUE(run.converged);
  for (size_t k = 0; k + 1 < run.trace.size(); ++k) {
    const bool survived = run.trace[k].episode_length == 50;
    EXPECT_NEAR(run.trace[k + 1].state[0] - run.trace[k].state[0],
                (survived ? -1.0 : 1.0) * run.trace[k].step_size, 1e-12);
  }
  EXPECT_NEAR(run.epsilon, 2.7, 10.0 * 2.0 * run.trace.back().step_size + 1e-9);
}

// survivor_value reports V at the last state that survived: at or above the boundary's 2.7.
TEST(EpsilonSearch, SurvivorValueIsTheLastSurvivingStatesValue) {
  const EpsilonSearchRun run = unit_gradient_search(/*survivor_value=*/true);
  double last_survivor = 0.0;
  for (const EpsilonSearchStep& step : run.trace) {
    if (step.episode_length == 50) last_survivor = step.value;
  }
  EXPECT_EQ(run.epsilon, last_survivor);
  EXPECT_GE(run.epsilon, 2.7);
  EXPECT_LT(run.epsilon, 2.7 + 10.0 * 0.2);
}

TEST(EpsilonSearch, TakesTheMaximumOverRestartsAndRedrawsNonPositiveStarts) {
  EpsilonSearchProblem problem = scripted_problem();
  int draws = 0;
  problem.sample_state = [&draws](Rng& rng) {
    ++draws;
    // Every other draw has V ≤ 0 and must be redrawn.
    return Eigen::VectorXd::Constant(1, draws % 2 == 1 ? -0.5 : rng.uniform(0.5, 1.5));
  };
  EpsilonSearchOptions options;
  options.step_size = 0.02;
  options.tolerance = 0.05;
  options.restarts = 5;
  Rng rng(11);
  const EpsilonSearchResult result = search_epsilon(problem, options, rng);
  ASSERT_EQ(result.runs.size(), 5u);
  EXPECT_EQ(draws, 10);
  double best = -1e300;
  for (const auto& run : result.runs) {
    EXPECT_GT(run.trace.front().value, 0.0);
    best = std::max(best, run.epsilon);
  }
  EXPECT_EQ(result.epsilon, best);
  EXPECT_NEAR(result.epsilon, 2.7, 0.15);
}

TEST(EpsilonSearch, FiniteDifferenceGradientOfAQuadratic) {
  const auto value = [](const Eigen::VectorXd& x) { return x[0] * x[0] + 3.0 * x[1]; };
  const Eigen::VectorXd g = finite_difference_gradient(value, Eigen::Vector2d(1.5, -2.0), 1e-4);
  EXPECT_NEAR(g[0], 3.0, 1e-8);
  EXPECT_NEAR(g[1], 3.0, 1e-8);
}

}  // namespace
}  // namespace tendril::safety
