#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/core/snapshot.hpp"

namespace tendril {

// A file of named values — integers, doubles, strings, float and double arrays, byte blobs
// (snapshots), random-stream states — with a kind ("checkpoint", "policy"), a format version
// and a CRC-32C over every byte. Checkpoints and model files are archives. The reader checks
// size, magic, version, kind and checksum before it interprets a single value, so a flipped
// bit, a zeroed block or a truncated file is refused with an Error naming the file, never
// read as different numbers.
//
// Layout (little-endian): "TNDRLARC", u32 version, kind (u32 length + bytes), u64 entry count,
// entries (u32 key length, key, u8 type, u64 payload length, payload), u32 CRC-32C of all
// bytes before it.
class ArchiveWriter {
 public:
  explicit ArchiveWriter(std::string kind) : kind_(std::move(kind)) {}

  // A key written twice keeps the last value.
  void put(const std::string& key, int64_t value);
  void put(const std::string& key, double value);
  void put(const std::string& key, std::string_view value);
  void put(const std::string& key, const char* value) { put(key, std::string_view(value)); }
  void put_floats(const std::string& key, std::span<const float> values);
  void put_floats(const std::string& key, const Eigen::Ref<const Eigen::VectorXf>& values) {
    put_floats(key, std::span<const float>(values.data(), static_cast<std::size_t>(values.size())));
  }
  void put_doubles(const std::string& key, std::span<const double> values);
  void put_bytes(const std::string& key, std::span<const std::byte> bytes);
  void put_rng(const std::string& key, const Rng& rng);

  // The file's bytes.
  std::string serialize() const;
  // Writes atomically (core/atomic_file): the old file or the new one, never a mixture.
  void commit(const std::filesystem::path& file) const;

 private:
  enum class Type : uint8_t;
  struct Entry {
    Type type;
    std::string payload;
  };
  void put_raw(const std::string& key, Type type, std::string payload);

  std::string kind_;
  std::map<std::string, Entry> entries_;
  friend class ArchiveReader;
};

class ArchiveReader {
 public:
  // Reads and verifies `file` (at most `max_bytes`); `kind` must match the writer's.
  ArchiveReader(const std::filesystem::path& file, std::string_view kind,
                uint64_t max_bytes = uint64_t{1} << 32);
  // The same for bytes in memory; `name` stands for the file in messages.
  static ArchiveReader from_bytes(std::string bytes, std::string_view kind, std::string name);

  bool contains(const std::string& key) const { return entries_.count(key) != 0; }
  int64_t get_int(const std::string& key) const;
  double get_double(const std::string& key) const;
  std::string get_string(const std::string& key) const;
  // Raises Error unless the entry holds exactly `size` floats (any size when size < 0).
  Eigen::VectorXf get_floats(const std::string& key, int64_t size = -1) const;
  std::vector<double> get_doubles(const std::string& key) const;
  Snapshot get_bytes(const std::string& key) const;
  Rng get_rng(const std::string& key) const;
  // An integer entry that must equal `expected` ("spec_observation_size is 4 in <file>, 3 here").
  void expect_int(const std::string& key, int64_t expected) const;

  const std::string& name() const { return name_; }
  std::vector<std::string> keys() const;

 private:
  ArchiveReader() = default;
  void parse(std::string bytes, std::string_view kind);
  const ArchiveWriter::Entry& entry(const std::string& key, ArchiveWriter::Type type,
                                    const char* type_name) const;
  [[noreturn]] void fail(const std::string& what) const;

  std::string name_;
  std::map<std::string, ArchiveWriter::Entry> entries_;
};

}  // namespace tendril
