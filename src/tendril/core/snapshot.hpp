#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tendril/core/rng.hpp"

namespace tendril {

// The exact state of something that evolves in time (a rod and its parts, an environment, a
// vector of environments), as bytes: what `save_state` writes, `load_state` restores, so that
// stepping on from a restored state repeats the original bit for bit. Sections are tagged, so a
// snapshot of another kind of object, or of another size, is refused with an Error naming the
// section instead of being misread.
using Snapshot = std::vector<std::byte>;

class SnapshotWriter {
 public:
  explicit SnapshotWriter(Snapshot& out) : out_(out) {}

  // Opens a section; SnapshotReader::section(name) checks it.
  void section(std::string_view name);
  void put(double value);
  void put(int64_t value);
  void put(uint64_t value);
  void put(bool value) { put(static_cast<uint64_t>(value)); }
  // A sequence with its length.
  void put(std::span<const double> values);
  // Rows, columns, then the values column by column (any storage order, any scalar as double).
  template <typename Derived>
  void put_matrix(const Eigen::DenseBase<Derived>& matrix) {
    put(static_cast<int64_t>(matrix.rows()));
    put(static_cast<int64_t>(matrix.cols()));
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) {
      for (Eigen::Index r = 0; r < matrix.rows(); ++r) put(static_cast<double>(matrix(r, c)));
    }
  }
  void put(const Rng& rng);

 private:
  void raw(const void* data, std::size_t size);
  Snapshot& out_;
};

// Reads what a SnapshotWriter wrote, in the same order. Every read checks the bytes left and
// every sized read the size expected; a mismatch raises Error naming the current section.
class SnapshotReader {
 public:
  explicit SnapshotReader(std::span<const std::byte> bytes) : bytes_(bytes) {}

  void section(std::string_view name);
  double get_double();
  int64_t get_int64();
  uint64_t get_uint64();
  bool get_bool();
  // Fills `values`, which must have the stored length.
  void get(std::span<double> values);
  // Fills `matrix`, which must have the stored shape.
  template <typename Derived>
  void get_matrix(Eigen::DenseBase<Derived>& matrix) {
    const int64_t rows = get_int64();
    const int64_t cols = get_int64();
    expect_shape(rows, cols, matrix.rows(), matrix.cols());
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) {
      for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
        matrix(r, c) = static_cast<typename Derived::Scalar>(get_double());
      }
    }
  }
  void get(Rng& rng);

  bool at_end() const { return offset_ == bytes_.size(); }
  // Raises Error unless every byte was read.
  void expect_end() const;

 private:
  void raw(void* data, std::size_t size);
  void expect_shape(int64_t rows, int64_t cols, Eigen::Index want_rows, Eigen::Index want_cols);
  [[noreturn]] void fail(const std::string& what) const;
  std::span<const std::byte> bytes_;
  std::size_t offset_ = 0;
  std::string section_ = "(start)";
};

// An environment's load_state all or nothing: loads `part` (a body, an arm, a plant: anything
// with save_state/load_state that restores itself all or nothing) from `in`, then runs
// `read_rest`, which reads the environment's other fields into copies and only then assigns
// them. If either throws, `part` is put back as it was and the error goes on, so a damaged or
// foreign snapshot leaves the environment exactly as it was.
template <typename Part, typename ReadRest>
void load_all_or_nothing(Part& part, SnapshotReader& in, ReadRest&& read_rest) {
  Snapshot before;
  SnapshotWriter writer(before);
  part.save_state(writer);
  part.load_state(in);
  try {
    read_rest();
  } catch (...) {
    SnapshotReader restore(before);
    part.load_state(restore);
    throw;
  }
}

}  // namespace tendril
