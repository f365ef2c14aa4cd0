#pragma once

#include <string>

#include "tendril/core/archive.hpp"
#include "tendril/nn/dense_mlp.hpp"

namespace tendril::nn {

// A DenseMlp's shape (sizes, hidden activation, tanh output) in and out of archives under
// `prefix` (policy files, checkpoints). Reading raises Error naming the archive on an
// implausible size.
void write_dense_mlp(ArchiveWriter& writer, const std::string& prefix, const DenseMlp& mlp);
DenseMlp read_dense_mlp(const ArchiveReader& reader, const std::string& prefix);

}  // namespace tendril::nn
