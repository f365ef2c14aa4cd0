#include "tendril/nn/threads.hpp"

#include <torch/torch.h>

#include "tendril/nn/blas.hpp"

namespace tendril::nn {

void use_one_torch_thread() {
  if (torch::get_num_threads() != 1) torch::set_num_threads(1);
  // OpenBLAS (behind LibTorch's BLAS calls and nn/blas) keeps a thread pool whose idle
  // threads spin and take the core the environments need.
  set_blas_threads(1);
}

}  // namespace tendril::nn
