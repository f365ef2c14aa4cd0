#include "tendril/core/snapshot.hpp"

#include <cstdio>
#include <cstring>

#include "tendril/core/error.hpp"

namespace tendril {

namespace {

// A section name read from damaged bytes, fit for a message: printable ASCII as it is, other
// bytes as \xNN, at most 64 of them.
std::string printable(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size() && i < 64; ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    }
  }
  if (name.size() > 64) out += "... (" + std::to_string(name.size()) + " bytes)";
  return out;
}

}  // namespace

void SnapshotWriter::raw(const void* data, std::size_t size) {
  const auto* begin = static_cast<const std::byte*>(data);
  out_.insert(out_.end(), begin, begin + size);
}

void SnapshotWriter::section(std::string_view name) {
  put(static_cast<uint64_t>(name.size()));
  raw(name.data(), name.size());
}

void SnapshotWriter::put(double value) { raw(&value, sizeof value); }
void SnapshotWriter::put(int64_t value) { raw(&value, sizeof value); }
void SnapshotWriter::put(uint64_t value) { raw(&value, sizeof value); }

void SnapshotWriter::put(std::span<const double> values) {
  put(static_cast<uint64_t>(values.size()));
  raw(values.data(), values.size_bytes());
}

void SnapshotWriter::put(const Rng& rng) {
  const Rng::State& state = rng.state();
  for (uint64_t word : state.words) put(word);
  put(state.spare_normal);
  put(state.has_spare_normal);
}

void SnapshotReader::fail(const std::string& what) const {
  throw Error(what, "snapshot section '" + section_ + "'");
}

void SnapshotReader::raw(void* data, std::size_t size) {
  if (bytes_.size() - offset_ < size) fail("the snapshot ends early");
  if (size == 0) return;  // an empty array's data() may be null, which memcpy must not be given
  std::memcpy(data, bytes_.data() + offset_, size);
  offset_ += size;
}

void SnapshotReader::section(std::string_view name) {
  const uint64_t length = get_uint64();
  if (length > bytes_.size() - offset_) fail("expected section '" + std::string(name) + "'");
  std::string found(length, '\0');
  raw(found.data(), length);
  if (found != name) {
    fail("expected section '" + std::string(name) + "', found '" + printable(found) + "'");
  }
  section_ = found;
}

double SnapshotReader::get_double() {
  double value = 0.0;
  raw(&value, sizeof value);
  return value;
}

int64_t SnapshotReader::get_int64() {
  int64_t value = 0;
  raw(&value, sizeof value);
  return value;
}

uint64_t SnapshotReader::get_uint64() {
  uint64_t value = 0;
  raw(&value, sizeof value);
  return value;
}

bool SnapshotReader::get_bool() {
  const uint64_t value = get_uint64();
  if (value > 1) fail("a flag holds " + std::to_string(value));
  return value == 1;
}

void SnapshotReader::get(std::span<double> values) {
  const uint64_t length = get_uint64();
  if (length != values.size()) {
    fail(std::to_string(length) + " values where " + std::to_string(values.size()) +
         " were expected");
  }
  raw(values.data(), values.size_bytes());
}

void SnapshotReader::expect_shape(int64_t rows, int64_t cols, Eigen::Index want_rows,
                                  Eigen::Index want_cols) {
  if (rows != want_rows || cols != want_cols) {
    fail("a " + std::to_string(rows) + " × " + std::to_string(cols) + " matrix where " +
         std::to_string(want_rows) + " × " + std::to_string(want_cols) + " was expected");
  }
}

void SnapshotReader::get(Rng& rng) {
  Rng::State state;
  for (uint64_t& word : state.words) word = get_uint64();
  state.spare_normal = get_double();
  state.has_spare_normal = get_bool();
  rng.set_state(state);
}

void SnapshotReader::expect_end() const {
  if (!at_end()) {
    throw Error(std::to_string(bytes_.size() - offset_) + " bytes left after the last section '" +
                    section_ + "'",
                "snapshot");
  }
}

}  // namespace tendril
