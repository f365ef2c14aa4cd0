#include "tendril/envs/hardware_info.hpp"

namespace tendril::envs {

HardwareInfo::HardwareInfo(std::unique_ptr<Env> inner, std::function<Measured()> measure)
    : Wrapper(std::move(inner)), measure_(std::move(measure)) {
  require(static_cast<bool>(measure_), "needs a measurement source", "HardwareInfo");
}

Step HardwareInfo::step(const Action& action) {
  Step result = inner_->step(action);
  const Measured measured = measure_();
  result.info.set("elapsed_s", measured.elapsed_s);
  result.info.set("latency_s", measured.latency_s);
  return result;
}

}  // namespace tendril::envs
