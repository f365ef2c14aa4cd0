// A rod step allocates nothing: global operator new is counted while the arms advance.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/rod/damping.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace tendril::physics {
namespace {

long allocations_while_advancing(ElasticaArm& arm, int steps) {
  const long before = allocations.load();
  EXPECT_TRUE(arm.rod.advance(steps));
  return allocations.load() - before;
}

TEST(RodAllocation, Case1ArmStepsWithoutAllocating) {
  ElasticaArm arm = build_elastica_arm(ElasticaArmSpec::tracking());
  arm.rod.add<AnalyticalLinearDamping>(0.1, 0.001);
  Eigen::VectorXd targets = Eigen::VectorXd::Constant(arm.muscles->spec().action_size(), 0.3);
  arm.muscles->set_targets(targets);
  EXPECT_EQ(allocations_while_advancing(arm, 500), 0);
}

TEST(RodAllocation, Case3ArmWithContactStepsWithoutAllocating) {
  ElasticaArm arm = build_elastica_arm(ElasticaArmSpec::structured_obstacles());
  arm.muscles->set_targets(Eigen::Vector2d(0.6, 0.6));
  ASSERT_TRUE(arm.rod.advance(4000));  // bend into the wall first
  EXPECT_EQ(allocations_while_advancing(arm, 1000), 0);
  EXPECT_GT(arm.contact->contacts(), 0) << "the arm should be touching the wall";
}

}  // namespace
}  // namespace tendril::physics
