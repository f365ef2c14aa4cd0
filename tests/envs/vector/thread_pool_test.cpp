#include "tendril/envs/vector/thread_pool.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <thread>

#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

TEST(ThreadPool, RunsEveryIndexExactlyOnceAcrossManyJobs) {
  ThreadPool pool(3);
  EXPECT_EQ(pool.num_threads(), 3);
  std::vector<int> calls(50, 0);
  for (int job = 0; job < 200; ++job) {
    pool.run(static_cast<int>(calls.size()), [&](int i) { calls[i] += 1; });
  }
  for (int count : calls) EXPECT_EQ(count, 200);
  pool.run(0, [](int) { FAIL() << "no index to run"; });
}

// A pool of two threads is the caller plus one worker: both take indices.
TEST(ThreadPool, UsesItsWorkersAndTheCaller) {
  ThreadPool pool(2);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::thread::id> ids(64);
  for (int attempt = 0; attempt < 100; ++attempt) {
    pool.run(64, [&](int i) {
      ids[i] = std::this_thread::get_id();
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    });
    const std::set<std::thread::id> distinct(ids.begin(), ids.end());
    ASSERT_LE(distinct.size(), 2u);
    if (distinct.size() == 2) {
      EXPECT_EQ(distinct.count(caller), 1u) << "the calling thread took no index";
      return;
    }
  }
  FAIL() << "the indices never spread over two threads";
}

TEST(ThreadPool, RethrowsATaskErrorAfterAllTasksFinish) {
  ThreadPool pool(2);
  std::vector<int> done(10, 0);
  try {
    pool.run(10, [&](int i) {
      if (i == 4) throw Error("task 4 failed", "test");
      done[i] = 1;
    });
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "test: task 4 failed");
  }
  EXPECT_EQ(std::count(done.begin(), done.end(), 1), 9);
  pool.run(10, [&](int i) { done[i] = 2; });  // the pool is still usable
  EXPECT_EQ(std::count(done.begin(), done.end(), 2), 10);
  EXPECT_THROW(ThreadPool(0), Error);
}

}  // namespace
}  // namespace tendril::envs
