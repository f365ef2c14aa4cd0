#include "tendril/dynamics/model_file_format.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "tendril/core/config.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

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

std::string header_text(const ModelFileContents& contents) {
  std::ostringstream out;
  out << description_yaml(contents.description) << "parameters:\n";
  for (const StoredParameter& p : contents.parameters) {
    out << "  - {name: " << p.name << ", shape: " << shape_text(p.shape) << "}\n";
  }
  return out.str();
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
  const char* last = line.data() + line.size();
  if (line.rfind(key + " ", 0) != 0 ||
      std::from_chars(line.data() + key.size() + 1, last, value).ptr != last) {
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

// The number of values of `shape`, refusing dimensions below 1 and products beyond `limit`.
int64_t element_count(const std::vector<int64_t>& shape, int64_t limit, const std::string& name,
                      const std::string& file) {
  require(!shape.empty(), "parameter '" + name + "' has no shape", file);
  int64_t count = 1;
  for (const int64_t size : shape) {
    require(size >= 1 && size <= limit / count,
            "parameter '" + name + "' has shape " + shape_text(shape) +
                ", more values than the file holds",
            file);
    count *= size;
  }
  return count;
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

std::string shape_text(const std::vector<int64_t>& shape) {
  std::string out = "[";
  for (std::size_t i = 0; i < shape.size(); ++i) out += (i ? ", " : "") + std::to_string(shape[i]);
  return out + "]";
}

std::string encode_model_file(const ModelFileContents& contents) {
  std::string payload;
  for (const StoredParameter& p : contents.parameters) {
    int64_t count = 1;
    for (const int64_t size : p.shape) count *= size;
    require(count == static_cast<int64_t>(p.values.size()),
            "parameter '" + p.name + "' of shape " + shape_text(p.shape) + " has " +
                std::to_string(p.values.size()) + " values",
            "dynamics::encode_model_file");
    payload.append(reinterpret_cast<const char*>(p.values.data()), p.values.size() * sizeof(float));
  }
  const std::string header = header_text(contents);
  std::string bytes = kMagic;
  bytes += "format " + std::to_string(kFormat) + "\n";
  bytes += "header_bytes " + std::to_string(header.size()) + "\n" + header;
  bytes += "payload_bytes " + std::to_string(payload.size()) + "\n" + payload;
  bytes += "crc32c " + checksum_text(crc32c(bytes.data(), bytes.size())) + "\n";
  return bytes;
}

ModelFileContents decode_model_file(const std::string& bytes, const std::string& file) {
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
  ModelFileContents contents;
  contents.description = read_description(header);

  // The table first, sizes only: nothing is allocated for values until the table agrees with
  // the architecture and with the payload.
  const int64_t payload_values = static_cast<int64_t>(payload_size / sizeof(float));
  int64_t total = 0;
  for (const Config& entry : header.children("parameters")) {
    StoredParameter p;
    p.name = entry.get<std::string>("name");
    p.shape = entry.get<std::vector<int64_t>>("shape");
    total += element_count(p.shape, payload_values - total, p.name, file);
    contents.parameters.push_back(std::move(p));
  }
  header.reject_unknown();
  const int64_t expected = contents.description.architecture.parameter_count();
  require(total == expected,
          "the file's parameter table holds " + std::to_string(total) +
              " values: they do not "
              "match the architecture's " +
              std::to_string(expected),
          file);
  require(payload_size == static_cast<uint64_t>(total) * sizeof(float),
          "payload has " + std::to_string(payload_size) + " bytes, the parameter table " +
              std::to_string(total * static_cast<int64_t>(sizeof(float))),
          file);

  std::size_t position = payload_offset;
  for (StoredParameter& p : contents.parameters) {
    int64_t count = 1;
    for (const int64_t size : p.shape) count *= size;
    p.values.resize(static_cast<std::size_t>(count));
    std::memcpy(p.values.data(), bytes.data() + position, p.values.size() * sizeof(float));
    position += p.values.size() * sizeof(float);
    // A crafted file may carry a correct checksum over weights no training produces.
    for (std::size_t i = 0; i < p.values.size(); ++i) {
      if (!std::isfinite(p.values[i])) {
        throw Error("parameter '" + p.name + "' holds a non-finite value (" +
                        std::to_string(p.values[i]) + ") at index " + std::to_string(i),
                    file);
      }
    }
  }
  return contents;
}

}  // namespace tendril::dynamics
