#include "tendril/nn/threads.hpp"

#include "tendril/nn/blas.hpp"

// Declared weak: present only when libblas.so.3 is OpenBLAS.
extern "C" int openblas_get_num_threads() __attribute__((weak));

namespace tendril::nn {

void configure_numerics(int blas_threads) { set_blas_threads(blas_threads); }

BlasThreads::BlasThreads(int threads)
    : previous_(openblas_get_num_threads != nullptr ? openblas_get_num_threads() : 1) {
  set_blas_threads(threads);
}

BlasThreads::~BlasThreads() { set_blas_threads(previous_ >= 1 ? previous_ : 1); }

}  // namespace tendril::nn
