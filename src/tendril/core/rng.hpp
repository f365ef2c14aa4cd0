#pragma once

#include <array>
#include <cstdint>

namespace tendril {

// A seeded random stream: xoshiro256** (Blackman & Vigna, 2018) seeded through splitmix64.
// Every consumer of randomness owns one, derived from the experiment seed and a stream id
// (one per environment, worker, or purpose), so runs are reproducible and independent of
// thread scheduling. The distributions are implemented here, not taken from <random>, whose
// distributions differ between standard libraries.
class Rng {
 public:
  struct State {
    std::array<uint64_t, 4> words{};
    double spare_normal = 0.0;
    bool has_spare_normal = false;
    bool operator==(const State&) const = default;
  };

  explicit Rng(uint64_t seed = 0, uint64_t stream = 0);

  // An independent stream derived from this generator's seed material and `stream`.
  Rng derive(uint64_t stream) const;

  uint64_t next_u64();
  double uniform();                        // [0, 1), 53 random bits
  double uniform(double low, double high); // [low, high)
  uint64_t below(uint64_t n);              // [0, n), unbiased
  double normal();                         // standard normal (Marsaglia polar method)
  double normal(double mean, double stddev) { return mean + stddev * normal(); }

  const State& state() const { return state_; }
  void set_state(const State& state) { state_ = state; }

 private:
  State state_;
  uint64_t seed_ = 0;
  uint64_t stream_ = 0;
};

}  // namespace tendril
