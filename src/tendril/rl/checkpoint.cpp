#include "tendril/rl/checkpoint.hpp"

#include <cstring>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"

namespace tendril::rl {

void CheckpointWriter::write_int(const std::string& key, int64_t value) {
  archive_.write(key, torch::tensor({value}, torch::kLong));
}

void CheckpointWriter::write_double(const std::string& key, double value) {
  archive_.write(key, torch::tensor({value}, torch::kDouble));
}

void CheckpointWriter::write_string(const std::string& key, const std::string& value) {
  archive_.write(key, c10::IValue(value));
}

void CheckpointWriter::write_doubles(const std::string& key, const std::vector<double>& values) {
  archive_.write(key, torch::tensor(values, torch::kDouble));
}

void CheckpointWriter::write_floats(const std::string& key, const Eigen::VectorXf& values) {
  archive_.write(
      key,
      torch::from_blob(const_cast<float*>(values.data()), {values.size()}, torch::kFloat).clone());
}

void CheckpointWriter::write_rng(const std::string& key, const Rng::State& state) {
  std::vector<int64_t> words;
  for (uint64_t word : state.words) {
    int64_t as_signed;
    std::memcpy(&as_signed, &word, sizeof word);
    words.push_back(as_signed);
  }
  archive_.write(key + "_words", torch::tensor(words, torch::kLong));
  write_double(key + "_spare_normal", state.spare_normal);
  write_int(key + "_has_spare_normal", state.has_spare_normal ? 1 : 0);
}

void CheckpointWriter::commit(const std::filesystem::path& file) {
  std::ostringstream stream;
  archive_.save_to(stream);
  const std::string bytes = std::move(stream).str();
  write_file_atomically(file, bytes, "checkpoint");
}

CheckpointReader::CheckpointReader(const std::filesystem::path& file) : file_(file) {
  require(std::filesystem::is_regular_file(file), "no checkpoint file", file.string());
  try {
    archive_.load_from(file.string());
  } catch (const c10::Error& e) {
    throw Error("corrupt or truncated checkpoint: " + e.msg(), file.string());
  } catch (const std::exception& e) {
    throw Error(std::string("corrupt or truncated checkpoint: ") + e.what(), file.string());
  }
}

bool CheckpointReader::contains(const std::string& key) {
  c10::IValue value;
  try {
    return archive_.try_read(key, value);
  } catch (const c10::Error&) {
    return false;
  }
}

torch::Tensor CheckpointReader::read_tensor(const std::string& key, torch::ScalarType type,
                                            int64_t numel) {
  torch::Tensor tensor;
  try {
    if (!archive_.try_read(key, tensor)) {
      throw Error("checkpoint has no entry '" + key + "'", file_.string());
    }
  } catch (const c10::Error& e) {
    throw Error("unreadable entry '" + key + "': " + e.msg(), file_.string());
  }
  if (tensor.scalar_type() != type || (numel >= 0 && tensor.numel() != numel)) {
    throw Error("entry '" + key + "' has the wrong type or size", file_.string());
  }
  return tensor.contiguous();
}

int64_t CheckpointReader::read_int(const std::string& key) {
  return read_tensor(key, torch::kLong, 1).item<int64_t>();
}

double CheckpointReader::read_double(const std::string& key) {
  return read_tensor(key, torch::kDouble, 1).item<double>();
}

std::string CheckpointReader::read_string(const std::string& key) {
  c10::IValue value;
  bool found = false;
  try {
    found = archive_.try_read(key, value);
  } catch (const c10::Error& e) {
    throw Error("unreadable entry '" + key + "': " + e.msg(), file_.string());
  }
  if (!found) throw Error("checkpoint has no entry '" + key + "'", file_.string());
  if (!value.isString()) throw Error("entry '" + key + "' is not a string", file_.string());
  return value.toStringRef();
}

std::vector<double> CheckpointReader::read_doubles(const std::string& key) {
  const torch::Tensor tensor = read_tensor(key, torch::kDouble);
  const double* data = tensor.data_ptr<double>();
  return std::vector<double>(data, data + tensor.numel());
}

Eigen::VectorXf CheckpointReader::read_floats(const std::string& key, int64_t size) {
  const torch::Tensor tensor = read_tensor(key, torch::kFloat, size);
  Eigen::VectorXf values(tensor.numel());
  std::copy_n(tensor.data_ptr<float>(), tensor.numel(), values.data());
  return values;
}

Rng::State CheckpointReader::read_rng(const std::string& key) {
  const torch::Tensor words = read_tensor(key + "_words", torch::kLong, 4);
  Rng::State state;
  for (int i = 0; i < 4; ++i) {
    const int64_t as_signed = words[i].item<int64_t>();
    std::memcpy(&state.words[i], &as_signed, sizeof as_signed);
  }
  state.spare_normal = read_double(key + "_spare_normal");
  state.has_spare_normal = read_int(key + "_has_spare_normal") != 0;
  return state;
}

void CheckpointReader::read_nested(
    const std::string& key, const std::function<void(torch::serialize::InputArchive&)>& load) {
  torch::serialize::InputArchive nested;
  try {
    if (!archive_.try_read(key, nested)) {
      throw Error("checkpoint has no entry '" + key + "'", file_.string());
    }
    load(nested);
  } catch (const c10::Error& e) {
    throw Error("unreadable entry '" + key + "': " + e.msg(), file_.string());
  }
}

}  // namespace tendril::rl
