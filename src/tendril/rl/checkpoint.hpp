#pragma once

#include <torch/torch.h>

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tendril/core/rng.hpp"

namespace tendril::rl {

// Writes a checkpoint: named scalars, vectors, RNG states and nested archives (module and
// optimizer state) into one torch::serialize archive, then `commit` puts it on disk atomically.
class CheckpointWriter {
 public:
  void write_int(const std::string& key, int64_t value);
  void write_double(const std::string& key, double value);
  void write_string(const std::string& key, const std::string& value);
  void write_doubles(const std::string& key, const std::vector<double>& values);
  void write_floats(const std::string& key, const Eigen::VectorXf& values);
  void write_rng(const std::string& key, const Rng::State& state);
  torch::serialize::OutputArchive& archive() { return archive_; }

  // Serialises to memory, writes a temporary file beside `file`, flushes it to disk and renames
  // it over `file`: a crash at any point leaves either the old checkpoint or the new one, never
  // a mixture. Raises Error (and leaves `file` untouched) if any step fails.
  void commit(const std::filesystem::path& file);

 private:
  torch::serialize::OutputArchive archive_;
};

// Reads a checkpoint written by CheckpointWriter. Every failure — missing, truncated or corrupt
// file, missing key, wrong type — raises tendril::Error naming the file and the key.
class CheckpointReader {
 public:
  explicit CheckpointReader(const std::filesystem::path& file);

  int64_t read_int(const std::string& key);
  double read_double(const std::string& key);
  std::string read_string(const std::string& key);
  std::vector<double> read_doubles(const std::string& key);
  // Raises Error unless the entry holds exactly `size` floats.
  Eigen::VectorXf read_floats(const std::string& key, int64_t size);
  Rng::State read_rng(const std::string& key);
  bool contains(const std::string& key);

  // Runs `load` (e.g. module->load(archive)) on the nested archive `key`, turning LibTorch's
  // errors into tendril::Error.
  void read_nested(const std::string& key,
                   const std::function<void(torch::serialize::InputArchive&)>& load);

  const std::filesystem::path& file() const { return file_; }

 private:
  torch::Tensor read_tensor(const std::string& key, torch::ScalarType type, int64_t numel = -1);

  std::filesystem::path file_;
  torch::serialize::InputArchive archive_;
};

}  // namespace tendril::rl
