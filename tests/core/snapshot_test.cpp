#include "tendril/core/snapshot.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

#include "support/error_message.hpp"

namespace tendril {
namespace {

TEST(Snapshot, RoundTripsEveryKindOfValueExactly) {
  Snapshot bytes;
  SnapshotWriter out(bytes);
  Rng rng(7, 3);
  rng.normal();  // leaves a spare normal behind
  const std::vector<double> values{1.0 / 3.0, -0.0, std::numeric_limits<double>::denorm_min()};
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor> rows(3, 2);
  rows << 1, 2, 3, 4, 5, 6;
  const Eigen::VectorXf floats = Eigen::VectorXf::LinSpaced(5, -1.0f, 1.0f);
  out.section("first");
  out.put(std::nan(""));
  out.put(int64_t{-42});
  out.put(uint64_t{1} << 63);
  out.put(true);
  out.put(std::span<const double>(values));
  out.section("second");
  out.put_matrix(rows);
  out.put_matrix(floats);
  out.put(rng);

  SnapshotReader in(bytes);
  in.section("first");
  EXPECT_TRUE(std::isnan(in.get_double()));
  EXPECT_EQ(in.get_int64(), -42);
  EXPECT_EQ(in.get_uint64(), uint64_t{1} << 63);
  EXPECT_TRUE(in.get_bool());
  std::vector<double> read(3);
  in.get(std::span<double>(read));
  EXPECT_EQ(read, values);
  EXPECT_TRUE(std::signbit(read[1]));
  in.section("second");
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor> rows_read(3, 2);
  in.get_matrix(rows_read);
  EXPECT_EQ(rows_read, rows);
  Eigen::VectorXf floats_read(5);
  in.get_matrix(floats_read);
  EXPECT_EQ(floats_read, floats);
  Rng restored(0);
  in.get(restored);
  EXPECT_EQ(restored.state(), rng.state());
  EXPECT_EQ(restored.normal(), rng.normal());
  EXPECT_TRUE(in.at_end());
  EXPECT_NO_THROW(in.expect_end());
}

// A part with one evolving value that restores itself all or nothing.
struct OneValuePart {
  double value = 0.0;
  void save_state(SnapshotWriter& out) const {
    out.section("part");
    out.put(value);
  }
  void load_state(SnapshotReader& in) {
    in.section("part");
    value = in.get_double();
  }
};

TEST(Snapshot, LoadAllOrNothingPutsThePartBackWhenTheRestCannotBeRead) {
  Snapshot saved;
  SnapshotWriter out(saved);
  OneValuePart{2.0}.save_state(out);
  out.put(7.0);  // the environment's own field after its part

  OneValuePart part{1.0};
  double field = 5.0;
  SnapshotReader whole(saved);
  load_all_or_nothing(part, whole, [&] { field = whole.get_double(); });
  EXPECT_EQ(part.value, 2.0);
  EXPECT_EQ(field, 7.0);

  // Cut inside the field: the part had loaded, and is put back; the field is untouched.
  part.value = 3.0;
  field = 4.0;
  const Snapshot cut(saved.begin(), saved.end() - 4);
  SnapshotReader short_read(cut);
  EXPECT_THROW(load_all_or_nothing(part, short_read, [&] { field = short_read.get_double(); }),
               Error);
  EXPECT_EQ(part.value, 3.0);
  EXPECT_EQ(field, 4.0);
}

TEST(Snapshot, MismatchesNameTheSection) {
  Snapshot bytes;
  SnapshotWriter out(bytes);
  out.section("Rod");
  out.put_matrix(Eigen::Matrix3d::Identity());
  out.put(1.5);

  {
    SnapshotReader in(bytes);
    EXPECT_EQ(testing::error_message([&] { in.section("Pendulum"); }),
              "snapshot section '(start)': expected section 'Pendulum', found 'Rod'");
  }
  {
    SnapshotReader in(bytes);
    in.section("Rod");
    Eigen::Matrix2d small;
    EXPECT_EQ(testing::error_message([&] { in.get_matrix(small); }),
              "snapshot section 'Rod': a 3 × 3 matrix where 2 × 2 was expected");
  }
  {
    SnapshotReader in(std::span<const std::byte>(bytes).first(bytes.size() - 4));
    in.section("Rod");
    Eigen::Matrix3d matrix;
    in.get_matrix(matrix);
    EXPECT_EQ(testing::error_message([&] { in.get_double(); }),
              "snapshot section 'Rod': the snapshot ends early");
  }
  {
    SnapshotReader in(bytes);
    in.section("Rod");
    EXPECT_EQ(testing::error_message([&] { in.expect_end(); }),
              "snapshot: 96 bytes left after the last section 'Rod'");
  }
}

TEST(Snapshot, AHugeSectionLengthIsRefusedWithoutAllocating) {
  Snapshot bytes;
  SnapshotWriter out(bytes);
  out.put(std::numeric_limits<uint64_t>::max());
  SnapshotReader in(bytes);
  EXPECT_EQ(testing::error_message([&] { in.section("Rod"); }),
            "snapshot section '(start)': expected section 'Rod'");
}

}  // namespace
}  // namespace tendril
