#pragma once

#include <cstdint>
#include <cstdlib>
#include <string>

namespace tendril::testing {

// The seed a learning test uses: `base` plus the environment variable TENDRIL_TEST_SEED_OFFSET
// (default 0). Another seed changes a run's trajectory as another CPU's rounding does, so running
// a learning test with offsets 0 … 7 (and under other BLAS kernel paths, OPENBLAS_CORETYPE)
// measures the margin of its threshold; docs/testing.md lists the measured margins.
inline uint64_t learning_seed(uint64_t base) {
  const char* offset = std::getenv("TENDRIL_TEST_SEED_OFFSET");
  if (offset == nullptr || *offset == '\0') return base;
  return base + std::stoull(offset);
}

}  // namespace tendril::testing
