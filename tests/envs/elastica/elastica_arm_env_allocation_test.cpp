// An Elastica RL step allocates only what it returns — the observation and one copy of the info
// entries — beyond what handing the action to the muscles costs (SplineActuation::set_targets,
// physics' side, counted separately). Every heap allocation is counted: operator new and
// Eigen's buffers both end in malloc, which this test wraps (glibc's __libc_malloc).
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>

#include "tendril/envs/elastica/structured_obstacles.hpp"
#include "tendril/envs/elastica/tracking_3d.hpp"
#include "tendril/envs/elastica/unstructured_obstacles.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* malloc(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}

namespace tendril::envs::elastica {
namespace {

long allocations_per_step(Env& env, const Action& action, int steps) {
  env.reset(0);
  // Let rate-limited control points (cases 3–4) reach the action first: while they move, the
  // muscles recompute their couples each physics step.
  for (int i = 0; i < 10; ++i) env.step(action);
  const long before = allocations.load();
  for (int i = 0; i < steps; ++i) {
    const Step step = env.step(action);
    EXPECT_FALSE(step.terminated);
  }
  return (allocations.load() - before) / steps;
}

long allocations_of_set_targets(ElasticaArmEnv& env, const Action& action) {
  const Eigen::VectorXd targets = action.cast<double>();
  const long before = allocations.load();
  env.arm().muscles->set_targets(targets);
  return allocations.load() - before;
}

TEST(ElasticaAllocation, StepAllocatesOnlyTheObservationAndInfo) {
  Tracking3D tracking;
  const Action tracking_action = Action::Constant(12, 0.3f);
  EXPECT_EQ(allocations_per_step(tracking, tracking_action, 50),
            2 + allocations_of_set_targets(tracking, tracking_action));

  StructuredObstacles::Params penalty;
  penalty.obstacle_mode = StructuredObstacles::ObstacleMode::kPenalty;
  StructuredObstacles structured(penalty);
  const Action structured_action = Action::Constant(2, 0.3f);
  EXPECT_EQ(allocations_per_step(structured, structured_action, 50),
            2 + allocations_of_set_targets(structured, structured_action));

  UnstructuredObstacles nest;
  const Action nest_action = Action::Constant(4, 0.3f);
  EXPECT_EQ(allocations_per_step(nest, nest_action, 50),
            2 + allocations_of_set_targets(nest, nest_action));
}

}  // namespace
}  // namespace tendril::envs::elastica
