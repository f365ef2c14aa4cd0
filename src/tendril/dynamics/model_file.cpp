#include "tendril/dynamics/model_file.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/model.hpp"

namespace tendril::dynamics {

namespace {

static_assert(std::endian::native == std::endian::little,
              "model files store little-endian floats; add byte swapping for this platform");

constexpr const char* kMagic = "tendril dynamics model\n";
constexpr int kFormat = 1;

std::string exact(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

std::string list(const std::vector<std::string>& names) {
  std::string out = "[";
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
  return out + "]";
}

std::string list(const Eigen::VectorXd& values) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < values.size(); ++i) out += (i ? ", " : "") + exact(values(i));
  return out + "]";
}

std::string shape_text(const std::vector<int64_t>& shape) {
  std::string out = "[";
  for (std::size_t i = 0; i < shape.size(); ++i) out += (i ? ", " : "") + std::to_string(shape[i]);
  return out + "]";
}

std::string header_text(const ModelDescription& d,
                        const std::vector<std::pair<std::string, torch::Tensor>>& parameters) {
  std::ostringstream out;
  out << description_yaml(d) << "parameters:\n";
  for (const auto& [name, tensor] : parameters) {
    out << "  - {name: " << name << ", shape: " << shape_text(tensor.sizes().vec()) << "}\n";
  }
  return out.str();
}

std::vector<std::pair<std::string, torch::Tensor>> named_parameters(const Model& model) {
  std::vector<std::pair<std::string, torch::Tensor>> result;
  for (const auto& item : const_cast<Model&>(model).network().named_parameters()) {
    result.emplace_back(item.key(), item.value());
  }
  return result;
}

// Reads the text line starting at `offset` ("<key> <value>\n"); advances past it.
std::string read_line(const std::string& bytes, std::size_t& offset, const std::string& file) {
  const std::size_t end = bytes.find('\n', offset);
  require(end != std::string::npos && end - offset < 256, "truncated model file", file);
  std::string line = bytes.substr(offset, end - offset);
  offset = end + 1;
  return line;
}

uint64_t read_count(const std::string& bytes, std::size_t& offset, const std::string& key,
                    const std::string& file) {
  const std::string line = read_line(bytes, offset, file);
  uint64_t value = 0;
  const char* first = line.data() + key.size() + 1;
  const char* last = line.data() + line.size();
  if (line.rfind(key + " ", 0) != 0 || std::from_chars(first, last, value).ptr != last) {
    throw Error("corrupt model file: expected '" + key + " <number>', found '" + line + "'", file);
  }
  return value;
}

ModelDescription read_description(const Config& header) {
  ModelDescription d;
  ArchitectureSpec& a = d.architecture;
  const std::string where = header.source();
  a.kind = parse_architecture(header.get<std::string>("architecture"), where);
  a.state_dim = header.get<int>("state_dim");
  a.input_dim = header.get<int>("input_dim");
  a.hidden_size = header.get<int>("hidden_size");
  a.layers = header.get<int>("layers");
  a.heads = header.get<int>("heads");
  a.window = header.get<int>("window");
  a.output_bound = header.get<double>("output_bound");
  a.dropout = header.get<double>("dropout");
  a.normalization = parse_normalization(header.get<std::string>("normalization"), where);
  d.state_names = header.get<std::vector<std::string>>("state_names");
  d.input_names = header.get<std::vector<std::string>>("input_names");
  d.sample_period = header.get<double>("sample_period_s");
  const Config normalizer = header.child("normalizer");
  const std::vector<double> offset = normalizer.get<std::vector<double>>("offset");
  const std::vector<double> scale = normalizer.get<std::vector<double>>("scale");
  d.normalizer.offset = Eigen::Map<const Eigen::VectorXd>(offset.data(), offset.size());
  d.normalizer.scale = Eigen::Map<const Eigen::VectorXd>(scale.data(), scale.size());
  d.validate(where);
  return d;
}

}  // namespace

std::string description_yaml(const ModelDescription& d) {
  const ArchitectureSpec& a = d.architecture;
  std::ostringstream out;
  out << "architecture: " << architecture_name(a.kind) << "\n"
      << "state_dim: " << a.state_dim << "\n"
      << "input_dim: " << a.input_dim << "\n"
      << "hidden_size: " << a.hidden_size << "\n"
      << "layers: " << a.layers << "\n"
      << "heads: " << a.heads << "\n"
      << "window: " << a.window << "\n"
      << "output_bound: " << exact(a.output_bound) << "\n"
      << "dropout: " << exact(a.dropout) << "\n"
      << "normalization: " << normalization_name(a.normalization) << "\n"
      << "state_names: " << list(d.state_names) << "\n"
      << "input_names: " << list(d.input_names) << "\n"
      << "sample_period_s: " << exact(d.sample_period) << "\n"
      << "normalizer:\n"
      << "  offset: " << list(d.normalizer.offset) << "\n"
      << "  scale: " << list(d.normalizer.scale) << "\n";
  return out.str();
}

ModelDescription parse_description_yaml(const std::string& yaml, const std::string& where) {
  const Config header = Config::parse(yaml, where);
  ModelDescription description = read_description(header);
  header.reject_unknown();
  return description;
}

std::filesystem::path model_file_path(const std::filesystem::path& file_or_run) {
  return std::filesystem::is_directory(file_or_run) ? file_or_run / kModelFileName : file_or_run;
}

void save_model(const Model& model, const std::filesystem::path& file, bool replace) {
  require(replace || !std::filesystem::exists(file), "exists; nothing is overwritten",
          file.string());
  const auto parameters = named_parameters(model);
  const std::string header = header_text(model.description(), parameters);
  std::string payload;
  for (const auto& [name, tensor] : parameters) {
    const torch::Tensor values = tensor.detach().to(torch::kFloat).contiguous();
    payload.append(reinterpret_cast<const char*>(values.data_ptr<float>()),
                   static_cast<std::size_t>(values.numel()) * sizeof(float));
  }
  std::string bytes = kMagic;
  bytes += "format " + std::to_string(kFormat) + "\n";
  bytes += "header_bytes " + std::to_string(header.size()) + "\n" + header;
  bytes += "payload_bytes " + std::to_string(payload.size()) + "\n" + payload;
  bytes += "crc32c " + checksum_text(crc32c(bytes.data(), bytes.size())) + "\n";
  write_file_atomically(file, bytes, "model file");
}

std::unique_ptr<Model> load_model(const std::filesystem::path& file_or_run) {
  const std::filesystem::path path = model_file_path(file_or_run);
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  require(in.good() && std::filesystem::is_regular_file(path), "no model file", file);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  require(bytes.rfind(kMagic, 0) == 0, "not a tendril dynamics model file", file);
  std::size_t offset = std::strlen(kMagic);
  const uint64_t format = read_count(bytes, offset, "format", file);
  require(format == kFormat,
          "model file format " + std::to_string(format) + "; this build reads format " +
              std::to_string(kFormat),
          file);
  const uint64_t header_size = read_count(bytes, offset, "header_bytes", file);
  require(header_size <= bytes.size() - offset, "truncated model file (header)", file);
  const std::string header_yaml = bytes.substr(offset, header_size);
  offset += header_size;
  const uint64_t payload_size = read_count(bytes, offset, "payload_bytes", file);
  require(payload_size <= bytes.size() - offset, "truncated model file (payload)", file);
  const std::size_t payload_offset = offset;
  offset += payload_size;
  const std::size_t checked = offset;
  const std::string checksum_line = read_line(bytes, offset, file);
  unsigned stored = 0;
  require(std::sscanf(checksum_line.c_str(), "crc32c %8x", &stored) == 1 && offset == bytes.size(),
          "truncated model file (no checksum at the end)", file);
  require(stored == crc32c(bytes.data(), checked),
          "corrupt model file: its checksum does not match its contents", file);

  const Config header = Config::parse(header_yaml, file);
  const ModelDescription description = read_description(header);
  auto model = std::make_unique<Model>(description, 0);
  const auto parameters = named_parameters(*model);
  const std::vector<Config> table = header.children("parameters");
  std::vector<std::string> expected, found;
  for (const auto& [name, tensor] : parameters) expected.push_back(name);
  for (const Config& entry : table) found.push_back(entry.get<std::string>("name"));
  require(
      expected == found,
      "the file's parameters " + list(found) + " do not match the architecture's " + list(expected),
      file);
  std::size_t position = payload_offset;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const auto& [name, tensor] = parameters[i];
    const std::vector<int64_t> shape = table[i].get<std::vector<int64_t>>("shape");
    require(shape == tensor.sizes().vec(),
            "parameter '" + name + "' has shape " + shape_text(shape) +
                " in the file, the architecture " + shape_text(tensor.sizes().vec()),
            file);
    const std::size_t size = static_cast<std::size_t>(tensor.numel()) * sizeof(float);
    require(position + size <= payload_offset + payload_size,
            "payload too short for parameter '" + name + "'", file);
    std::vector<float> values(static_cast<std::size_t>(tensor.numel()));
    std::memcpy(values.data(), bytes.data() + position, size);
    torch::NoGradGuard no_grad;
    torch::Tensor target = tensor;
    target.copy_(torch::from_blob(values.data(), tensor.sizes(), torch::kFloat));
    position += size;
  }
  require(position == payload_offset + payload_size,
          "payload has " + std::to_string(payload_offset + payload_size - position) +
              " bytes more than the parameters",
          file);
  header.reject_unknown();
  return model;
}

}  // namespace tendril::dynamics
