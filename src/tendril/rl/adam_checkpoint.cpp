#include "tendril/rl/adam_checkpoint.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

void save_adam(CheckpointWriter& writer, const std::string& prefix, const nn::Adam& adam) {
  writer.write_int(prefix + "_steps", adam.steps());
  writer.write_floats(prefix + "_m", adam.first_moment());
  writer.write_floats(prefix + "_v", adam.second_moment());
}

std::function<void()> prepare_adam(CheckpointReader& reader, const std::string& prefix,
                                   nn::Adam& adam, int64_t parameter_count) {
  const int64_t steps = reader.read_int(prefix + "_steps");
  Eigen::VectorXf first = reader.read_floats(prefix + "_m", parameter_count);
  Eigen::VectorXf second = reader.read_floats(prefix + "_v", parameter_count);
  require(steps >= 0, "negative optimizer step count", reader.file().string());
  return [&adam, steps, first, second] { adam.set_state(steps, first, second); };
}

}  // namespace tendril::rl
