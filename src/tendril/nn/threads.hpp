#pragma once

namespace tendril::nn {

// Restricts LibTorch to one intra-op thread. The small networks of control tasks are dominated
// by per-call overhead, and on two-core machines a second thread makes them several times
// slower (SAC at 105 vs 25 steps/s measured on such a machine). OpenBLAS is held to one
// thread too. Idempotent.
void use_one_torch_thread();

}  // namespace tendril::nn
