#pragma once

#include <functional>
#include <memory>

#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

// A robot environment over a hardware bridge: the twin version's every key and value, plus
// what only a link to a robot has — "elapsed_s", the wall-clock time since reset, and
// "latency_s", the step's command round trip (s).
class HardwareInfo final : public Wrapper {
 public:
  struct Measured {
    double elapsed_s = 0.0;
    double latency_s = 0.0;
  };

  HardwareInfo(std::unique_ptr<Env> inner, std::function<Measured()> measure);

  Step step(const Action& action) override;

 private:
  std::function<Measured()> measure_;
};

}  // namespace tendril::envs
