#include "tendril/rl/adam_checkpoint.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

void save_adam(ArchiveWriter& writer, const std::string& prefix, const nn::Adam& adam) {
  writer.put(prefix + "_steps", adam.steps());
  writer.put_floats(prefix + "_m", adam.first_moment());
  writer.put_floats(prefix + "_v", adam.second_moment());
}

std::function<void()> prepare_adam(const ArchiveReader& reader, const std::string& prefix,
                                   nn::Adam& adam, int64_t parameter_count) {
  const int64_t steps = reader.get_int(prefix + "_steps");
  Eigen::VectorXf first = reader.get_floats(prefix + "_m", parameter_count);
  Eigen::VectorXf second = reader.get_floats(prefix + "_v", parameter_count);
  require(steps >= 0, "negative optimizer step count", reader.name());
  return [&adam, steps, first, second] { adam.set_state(steps, first, second); };
}

}  // namespace tendril::rl
