#pragma once

namespace tendril::dynamics {

// Restricts LibTorch to one intra-op thread and OpenBLAS to one thread (nn::configure_numerics).
// The recurrent models' small products are dominated by per-call overhead, and on two-core
// machines a second thread makes them several times slower. Idempotent.
void use_one_torch_thread();

}  // namespace tendril::dynamics
