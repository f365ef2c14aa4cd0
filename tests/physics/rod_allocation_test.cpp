// A rod step allocates nothing: every heap allocation of the process (malloc and its relatives,
// which operator new and Eigen both use) is counted while the arms advance and are actuated.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <limits>

#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/rod/rod_pool.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);

void* malloc(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(pointer, size);
}
int posix_memalign(void** pointer, std::size_t alignment, std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  *pointer = __libc_memalign(alignment, size);
  return *pointer ? 0 : 12;  // ENOMEM
}
}

namespace tendril::physics {
namespace {

// `actions` RL steps: new control-point targets around `bias`, then one action's substeps.
long allocations_while_acting(ElasticaArm& arm, int actions, int substeps, double bias,
                              double level) {
  Eigen::VectorXd targets(arm.muscles->spec().action_size());
  const long before = allocations.load();
  for (int a = 0; a < actions; ++a) {
    for (Eigen::Index k = 0; k < targets.size(); ++k) targets[k] = bias + level * ((a + k) % 3 - 1);
    arm.muscles->set_targets(targets);
    EXPECT_TRUE(arm.rod.advance(substeps));
  }
  return allocations.load() - before;
}

TEST(RodAllocation, CountingSeesAllocations) {
  const long before = allocations.load();
  Eigen::VectorXd v = Eigen::VectorXd::Ones(100);
  std::vector<int> w(10);
  EXPECT_GE(allocations.load() - before, 2) << v.sum() << w.size();
}

TEST(RodAllocation, Case1ArmActsWithoutAllocating) {
  ElasticaArm arm = build_elastica_arm(ElasticaArmSpec::tracking());
  arm.rod.add<AnalyticalLinearDamping>(0.1, 0.001);
  EXPECT_EQ(allocations_while_acting(arm, 100, 7, 0.0, 0.3), 0);
}

TEST(RodAllocation, Case3ArmWithContactAndRateLimitActsWithoutAllocating) {
  ElasticaArm arm = build_elastica_arm(ElasticaArmSpec::structured_obstacles());
  arm.muscles->set_targets(Eigen::Vector2d(0.6, 0.6));
  ASSERT_TRUE(arm.rod.advance(4000));  // bend into the wall first
  // Targets far from the current control points: the rate limit moves them every substep.
  EXPECT_EQ(allocations_while_acting(arm, 50, 14, 0.6, 0.3), 0);
  EXPECT_GT(arm.contact->contacts(), 0) << "the arm should be touching the wall";
}

// Implicit steps allocate nothing either, once a first step has sized the buffer that holds
// the parts' state at a step's start (to undo a failed step).
TEST(RodAllocation, ImplicitArmsActWithoutAllocating) {
  for (RodIntegrator integrator : {RodIntegrator::kBackwardEuler, RodIntegrator::kBdf2}) {
    ElasticaArmSpec tracking = ElasticaArmSpec::tracking();
    tracking.integrator = integrator;
    ElasticaArm arm = build_elastica_arm(tracking);
    arm.rod.add<AnalyticalLinearDamping>(0.1, 0.001);
    ASSERT_TRUE(arm.rod.advance(1));
    EXPECT_EQ(allocations_while_acting(arm, 100, 1, 0.0, 0.3), 0) << integrator_name(integrator);

    ElasticaArmSpec obstacles = ElasticaArmSpec::structured_obstacles();
    obstacles.integrator = integrator;
    ElasticaArm case3 = build_elastica_arm(obstacles);
    case3.muscles->set_targets(Eigen::Vector2d(0.6, 0.6));
    ASSERT_TRUE(case3.rod.advance(300));  // bend into the wall first
    EXPECT_EQ(allocations_while_acting(case3, 50, 1, 0.6, 0.3), 0) << integrator_name(integrator);
    EXPECT_GT(case3.contact->contacts(), 0) << "the arm should be touching the wall";
  }
}

// Eleven case-1 arms in a RodPool (a full block and a partial one), with rate-limited muscles
// and one rod stopped by a non-finite state: commanding and advancing them allocates nothing.
TEST(RodAllocation, RodPoolActsWithoutAllocating) {
  ElasticaArmSpec spec = ElasticaArmSpec::tracking();
  spec.actuation.max_change_per_step = 0.01;
  const ElasticaArm prototype = build_elastica_arm(spec);
  RodPool pool(prototype.rod, 11);
  RodState stopped = prototype.rod.state();
  stopped.velocities(0, 3) = std::numeric_limits<double>::quiet_NaN();
  pool.set_state(7, stopped);
  Eigen::VectorXd targets(spec.actuation.action_size());
  const long before = allocations.load();
  for (int a = 0; a < 50; ++a) {
    for (int r = 0; r < pool.size(); ++r) {
      for (Eigen::Index k = 0; k < targets.size(); ++k) targets[k] = 0.3 * ((a + k + r) % 3 - 1);
      pool.set_targets(r, targets);
    }
    EXPECT_FALSE(pool.advance(7));
  }
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_TRUE(pool.is_finite(6) && !pool.is_finite(7));
}

}  // namespace
}  // namespace tendril::physics
