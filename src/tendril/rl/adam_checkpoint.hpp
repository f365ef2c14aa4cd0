#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "tendril/core/archive.hpp"
#include "tendril/nn/adam.hpp"

namespace tendril::rl {

// An Adam optimizer's state in and out of a checkpoint under `prefix`. `prepare_adam` reads
// and checks it (Error if the moments do not have `parameter_count` entries) and returns the
// action that installs it.
void save_adam(ArchiveWriter& writer, const std::string& prefix, const nn::Adam& adam);
std::function<void()> prepare_adam(const ArchiveReader& reader, const std::string& prefix,
                                   nn::Adam& adam, int64_t parameter_count);

}  // namespace tendril::rl
