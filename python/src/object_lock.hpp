#pragma once

#include <pybind11/pybind11.h>

#include <mutex>

namespace tendril::python {

// Serializes the calls into one extension object made from several Python threads. The C++
// objects behind Env, VecEnv and Policy keep working buffers (a vector env's batches and infos,
// a policy's observation matrix, an environment's state) that the GIL does not protect once a
// call releases it to compute: a second thread entering meanwhile would resize or rewrite them.
//
// The lock is only ever waited for with the GIL released, while its holder may take the GIL back
// (to build its answer): a thread blocked on the lock while holding the GIL would deadlock with
// it. Uncontended, it is taken without touching the GIL.
class ObjectLock {
 public:
  std::unique_lock<std::mutex> acquire() {
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) {
      pybind11::gil_scoped_release release;
      lock.lock();
    }
    return lock;
  }

 private:
  std::mutex mutex_;
};

}  // namespace tendril::python
