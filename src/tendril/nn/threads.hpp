#pragma once

namespace tendril::nn {

// Settings of the process's numerical libraries, made once at a program's boundary (the
// command line's main, the Python module's initialisation), never by an algorithm: OpenBLAS
// may use `blas_threads` threads for one product (nn/blas), and its idle threads must not spin
// on the core the environments need. Algorithms that want another count for their own
// products (off-policy `learner_threads`) scope it with BlasThreads.
void configure_numerics(int blas_threads = 1);

// Sets OpenBLAS's thread count for its lifetime and restores the previous one after.
class BlasThreads {
 public:
  explicit BlasThreads(int threads);
  ~BlasThreads();
  BlasThreads(const BlasThreads&) = delete;
  BlasThreads& operator=(const BlasThreads&) = delete;

 private:
  int previous_;
};

}  // namespace tendril::nn
