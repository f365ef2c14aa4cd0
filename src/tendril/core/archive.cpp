#include "tendril/core/archive.hpp"

#include <cstring>
#include <fstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril {

enum class ArchiveWriter::Type : uint8_t {
  kInt = 1,
  kDouble = 2,
  kString = 3,
  kFloats = 4,
  kDoubles = 5,
  kBytes = 6,
};

namespace {

constexpr char kMagic[8] = {'T', 'N', 'D', 'R', 'L', 'A', 'R', 'C'};
constexpr uint32_t kVersion = 1;

template <typename T>
void append(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void append_string(std::string& out, std::string_view text) {
  append(out, static_cast<uint32_t>(text.size()));
  out.append(text);
}

std::string bytes_of(const void* data, std::size_t size) {
  return std::string(static_cast<const char*>(data), size);
}

// Sequential reads over verified bytes; running past the end is still checked.
class Cursor {
 public:
  Cursor(const std::string& bytes, std::size_t end) : bytes_(bytes), end_(end) {}
  bool take(void* out, std::size_t size) {
    if (end_ - offset_ < size) return false;
    if (size > 0) std::memcpy(out, bytes_.data() + offset_, size);
    offset_ += size;
    return true;
  }
  bool take_string(std::string& out, uint64_t size) {
    if (end_ - offset_ < size) return false;
    out.assign(bytes_.data() + offset_, size);
    offset_ += size;
    return true;
  }
  bool at_end() const { return offset_ == end_; }

 private:
  const std::string& bytes_;
  std::size_t end_;
  std::size_t offset_ = 0;
};

}  // namespace

void ArchiveWriter::put_raw(const std::string& key, Type type, std::string payload) {
  require(!key.empty(), "archive keys must not be empty", "ArchiveWriter");
  entries_[key] = Entry{type, std::move(payload)};
}

void ArchiveWriter::put(const std::string& key, int64_t value) {
  put_raw(key, Type::kInt, bytes_of(&value, sizeof value));
}

void ArchiveWriter::put(const std::string& key, double value) {
  put_raw(key, Type::kDouble, bytes_of(&value, sizeof value));
}

void ArchiveWriter::put(const std::string& key, std::string_view value) {
  put_raw(key, Type::kString, std::string(value));
}

void ArchiveWriter::put_floats(const std::string& key, std::span<const float> values) {
  put_raw(key, Type::kFloats, bytes_of(values.data(), values.size_bytes()));
}

void ArchiveWriter::put_doubles(const std::string& key, std::span<const double> values) {
  put_raw(key, Type::kDoubles, bytes_of(values.data(), values.size_bytes()));
}

void ArchiveWriter::put_bytes(const std::string& key, std::span<const std::byte> bytes) {
  put_raw(key, Type::kBytes, bytes_of(bytes.data(), bytes.size()));
}

void ArchiveWriter::put_rng(const std::string& key, const Rng& rng) {
  Snapshot bytes;
  SnapshotWriter writer(bytes);
  writer.put(rng);
  put_bytes(key, bytes);
}

std::string ArchiveWriter::serialize() const {
  std::string out(kMagic, sizeof kMagic);
  append(out, kVersion);
  append_string(out, kind_);
  append(out, static_cast<uint64_t>(entries_.size()));
  for (const auto& [key, entry] : entries_) {
    append_string(out, key);
    append(out, static_cast<uint8_t>(entry.type));
    append(out, static_cast<uint64_t>(entry.payload.size()));
    out.append(entry.payload);
  }
  append(out, crc32c(out.data(), out.size()));
  return out;
}

void ArchiveWriter::commit(const std::filesystem::path& file) const {
  write_file_atomically(file, serialize(), kind_);
}

ArchiveReader::ArchiveReader(const std::filesystem::path& file, std::string_view kind,
                             uint64_t max_bytes)
    : name_(file.string()) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    fail(std::filesystem::exists(file, error) ? "not a regular file" : "no such file");
  }
  const uintmax_t size = std::filesystem::file_size(file, error);
  if (error) fail("cannot read its size: " + error.message());
  if (size > max_bytes) {
    fail("is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
         " a " + std::string(kind) + " may have");
  }
  std::ifstream in(file, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size))) fail("cannot be read");
  parse(std::move(bytes), kind);
}

ArchiveReader ArchiveReader::from_bytes(std::string bytes, std::string_view kind,
                                        std::string name) {
  ArchiveReader reader;
  reader.name_ = std::move(name);
  reader.parse(std::move(bytes), kind);
  return reader;
}

void ArchiveReader::fail(const std::string& what) const { throw Error(what, name_); }

void ArchiveReader::parse(std::string bytes, std::string_view kind) {
  const std::string what = "not a tendril " + std::string(kind) + " file";
  if (bytes.size() < sizeof kMagic + sizeof(uint32_t) * 2 ||
      std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    fail(what + " (no archive header)");
  }
  uint32_t stored_crc = 0;
  std::memcpy(&stored_crc, bytes.data() + bytes.size() - sizeof stored_crc, sizeof stored_crc);
  const std::size_t body = bytes.size() - sizeof stored_crc;
  if (crc32c(bytes.data(), body) != stored_crc) {
    fail("corrupt " + std::string(kind) +
         " file: checksum mismatch (the file was damaged or cut "
         "short)");
  }
  Cursor cursor(bytes, body);
  char magic[sizeof kMagic];
  cursor.take(magic, sizeof magic);
  uint32_t version = 0, kind_size = 0;
  cursor.take(&version, sizeof version);
  if (version != kVersion) {
    fail("archive format " + std::to_string(version) + " is not supported (this build reads " +
         std::to_string(kVersion) + ")");
  }
  std::string found_kind;
  if (!cursor.take(&kind_size, sizeof kind_size) || !cursor.take_string(found_kind, kind_size)) {
    fail("malformed archive header");
  }
  if (found_kind != kind) fail("a " + found_kind + " file, not a " + std::string(kind) + " file");
  uint64_t count = 0;
  if (!cursor.take(&count, sizeof count)) fail("malformed archive header");
  for (uint64_t i = 0; i < count; ++i) {
    uint32_t key_size = 0;
    std::string key;
    uint8_t type = 0;
    uint64_t payload_size = 0;
    ArchiveWriter::Entry entry;
    if (!cursor.take(&key_size, sizeof key_size) || !cursor.take_string(key, key_size) ||
        !cursor.take(&type, sizeof type) || !cursor.take(&payload_size, sizeof payload_size) ||
        !cursor.take_string(entry.payload, payload_size) || type < 1 || type > 6) {
      fail("malformed archive entry " + std::to_string(i));
    }
    entry.type = static_cast<ArchiveWriter::Type>(type);
    entries_[key] = std::move(entry);
  }
  if (!cursor.at_end()) fail("malformed archive: bytes after the last entry");
}

const ArchiveWriter::Entry& ArchiveReader::entry(const std::string& key, ArchiveWriter::Type type,
                                                 const char* type_name) const {
  const auto found = entries_.find(key);
  if (found == entries_.end()) fail("missing entry '" + key + "'");
  if (found->second.type != type) fail("entry '" + key + "' is not " + type_name);
  return found->second;
}

int64_t ArchiveReader::get_int(const std::string& key) const {
  const auto& payload = entry(key, ArchiveWriter::Type::kInt, "an integer").payload;
  int64_t value = 0;
  if (payload.size() != sizeof value) fail("entry '" + key + "' is malformed");
  std::memcpy(&value, payload.data(), sizeof value);
  return value;
}

double ArchiveReader::get_double(const std::string& key) const {
  const auto& payload = entry(key, ArchiveWriter::Type::kDouble, "a number").payload;
  double value = 0;
  if (payload.size() != sizeof value) fail("entry '" + key + "' is malformed");
  std::memcpy(&value, payload.data(), sizeof value);
  return value;
}

std::string ArchiveReader::get_string(const std::string& key) const {
  return entry(key, ArchiveWriter::Type::kString, "a string").payload;
}

Eigen::VectorXf ArchiveReader::get_floats(const std::string& key, int64_t size) const {
  const auto& payload = entry(key, ArchiveWriter::Type::kFloats, "a float array").payload;
  if (payload.size() % sizeof(float) != 0) fail("entry '" + key + "' is malformed");
  const auto count = static_cast<int64_t>(payload.size() / sizeof(float));
  if (size >= 0 && count != size) {
    fail("entry '" + key + "' holds " + std::to_string(count) + " values, expected " +
         std::to_string(size));
  }
  Eigen::VectorXf values(count);
  // An empty array has no storage (a null pointer, which memcpy must not be given).
  if (count > 0) std::memcpy(values.data(), payload.data(), payload.size());
  return values;
}

std::vector<double> ArchiveReader::get_doubles(const std::string& key) const {
  const auto& payload = entry(key, ArchiveWriter::Type::kDoubles, "a double array").payload;
  if (payload.size() % sizeof(double) != 0) fail("entry '" + key + "' is malformed");
  std::vector<double> values(payload.size() / sizeof(double));
  if (!values.empty()) std::memcpy(values.data(), payload.data(), payload.size());
  return values;
}

Snapshot ArchiveReader::get_bytes(const std::string& key) const {
  const auto& payload = entry(key, ArchiveWriter::Type::kBytes, "a byte blob").payload;
  const auto* begin = reinterpret_cast<const std::byte*>(payload.data());
  return Snapshot(begin, begin + payload.size());
}

Rng ArchiveReader::get_rng(const std::string& key) const {
  const Snapshot bytes = get_bytes(key);
  SnapshotReader reader(bytes);
  Rng rng(0);
  try {
    reader.get(rng);
    reader.expect_end();
  } catch (const Error& e) {
    fail("entry '" + key + "' is not a random-stream state: " + e.what());
  }
  return rng;
}

void ArchiveReader::expect_int(const std::string& key, int64_t expected) const {
  const int64_t found = get_int(key);
  if (found != expected) {
    fail(key + " is " + std::to_string(found) + " in the file, " + std::to_string(expected) +
         " here");
  }
}

std::vector<std::string> ArchiveReader::keys() const {
  std::vector<std::string> result;
  for (const auto& item : entries_) result.push_back(item.first);
  return result;
}

}  // namespace tendril
