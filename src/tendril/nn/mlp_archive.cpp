#include "tendril/nn/mlp_archive.hpp"

#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::nn {

void write_dense_mlp(ArchiveWriter& writer, const std::string& prefix, const DenseMlp& mlp) {
  writer.put_doubles(prefix + "_sizes",
                     std::vector<double>(mlp.sizes().begin(), mlp.sizes().end()));
  writer.put(prefix + "_activation", activation_name(mlp.hidden_activation()));
  writer.put(prefix + "_tanh_output", int64_t{mlp.tanh_output()});
}

DenseMlp read_dense_mlp(const ArchiveReader& reader, const std::string& prefix) {
  const std::vector<double> sizes = reader.get_doubles(prefix + "_sizes");
  for (double size : sizes) {
    if (!(size >= 1 && size <= 1e6) || size != static_cast<double>(static_cast<int64_t>(size))) {
      throw Error("implausible layer size in '" + prefix + "_sizes'", reader.name());
    }
  }
  return DenseMlp(std::vector<int64_t>(sizes.begin(), sizes.end()),
                  parse_activation(reader.get_string(prefix + "_activation"), reader.name()),
                  reader.get_int(prefix + "_tanh_output") != 0);
}

}  // namespace tendril::nn
