#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace tendril::envs {

// A fixed set of worker threads, started once and reused for every call to `run` (starting
// threads per step would cost more than stepping a small environment). The calling thread works
// too, so `num_threads` counts it: ThreadPool(4) starts 3 workers.
class ThreadPool {
 public:
  explicit ThreadPool(int num_threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int num_threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls task(i) once for every i in [0, count), spread over the workers and the calling
  // thread, and returns when all calls have finished. Which thread runs which index is not
  // fixed, so tasks must write only to their own index's data. If tasks throw, the exception
  // of one of them is rethrown here after all have finished. Not reentrant: one caller at a time.
  void run(int count, const std::function<void(int)>& task);

 private:
  void worker_loop();
  void drain();  // runs tasks until the indices of the current job are used up

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable job_ready_;
  std::condition_variable job_done_;
  uint64_t generation_ = 0;  // incremented per job; workers wait for a change
  int busy_workers_ = 0;
  bool stopping_ = false;

  const std::function<void(int)>* task_ = nullptr;
  int count_ = 0;
  std::atomic<int> next_index_{0};
  std::exception_ptr error_;
};

}  // namespace tendril::envs
