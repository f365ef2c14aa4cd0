#include "tendril/nn/threads.hpp"

#include <torch/torch.h>

// OpenBLAS (Debian's libopenblas0-pthread, behind LibTorch's BLAS calls) starts its own thread
// pool, whose idle threads spin and take the core the environments need. Declared weak: absent
// when another BLAS is installed.
extern "C" void openblas_set_num_threads(int threads) __attribute__((weak));

namespace tendril::nn {

void use_one_torch_thread() {
  if (torch::get_num_threads() != 1) torch::set_num_threads(1);
  static const bool blas_limited = [] {
    if (openblas_set_num_threads != nullptr) openblas_set_num_threads(1);
    return true;
  }();
  (void)blas_limited;
}

}  // namespace tendril::nn
