#include "tendril/dynamics/torch_threads.hpp"

#include <torch/torch.h>

#include "tendril/nn/threads.hpp"

namespace tendril::dynamics {

void use_one_torch_thread() {
  torch::set_num_threads(1);
  nn::configure_numerics(1);
}

}  // namespace tendril::dynamics
