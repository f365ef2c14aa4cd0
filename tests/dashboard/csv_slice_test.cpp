#include "tendril/dashboard/csv_slice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

namespace tendril::dashboard {
namespace {

namespace fs = std::filesystem;

class CsvSliceTest : public testing::ScratchDirectoryTest {
 protected:
  CsvSliceTest() : ScratchDirectoryTest("csv_slice") {}
  fs::path write(const std::string& text) {
    const fs::path file = directory_ / "progress.csv";
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    return file;
  }
};

TEST_F(CsvSliceTest, ReadsColumnsAndNumericRowsWithEmptyCellsAsNaN) {
  const fs::path file = write("time/total_timesteps,rollout/ep_rew_mean\n2048,-1200.5\n4096,\n");
  const CsvSlice slice = read_csv_slice(file, 0);
  ASSERT_EQ(slice.columns,
            (std::vector<std::string>{"time/total_timesteps", "rollout/ep_rew_mean"}));
  ASSERT_EQ(slice.rows.size(), 2u);
  EXPECT_EQ(slice.rows[0], (std::vector<double>{2048, -1200.5}));
  EXPECT_EQ(slice.rows[1][0], 4096);
  EXPECT_TRUE(std::isnan(slice.rows[1][1]));
  EXPECT_EQ(slice.first_line, 2);
  EXPECT_EQ(slice.next_offset, fs::file_size(file));
  EXPECT_TRUE(slice.problems.empty());
  EXPECT_FALSE(slice.partial_line);
}

TEST_F(CsvSliceTest, FollowsAGrowingFileFromTheLastOffset) {
  std::string text = "t,r\n1,10\n2,20\n";
  const CsvSlice first = read_csv_slice(write(text), 0);
  ASSERT_EQ(first.rows.size(), 2u);
  text += "3,30\n4,4";  // the last line is still being written
  const CsvSlice second = read_csv_slice(write(text), first.next_offset);
  ASSERT_EQ(second.rows.size(), 1u);
  EXPECT_EQ(second.rows[0], (std::vector<double>{3, 30}));
  EXPECT_EQ(second.first_line, 4);
  EXPECT_TRUE(second.partial_line);
  EXPECT_EQ(second.next_offset, text.size() - 3);
  text += "0\n";
  const CsvSlice third = read_csv_slice(write(text), second.next_offset);
  ASSERT_EQ(third.rows.size(), 1u);
  EXPECT_EQ(third.rows[0], (std::vector<double>{4, 40}));
  EXPECT_FALSE(third.restarted);
}

TEST_F(CsvSliceTest, AFileRewrittenShorterOrShiftedIsReadFromItsStart) {
  const std::string text = "t,r,extra\n1,10,0\n";
  const CsvSlice past_end = read_csv_slice(write(text), 500);
  EXPECT_TRUE(past_end.restarted);
  EXPECT_EQ(past_end.rows.size(), 1u);
  const CsvSlice mid_line = read_csv_slice(write(text), 12);  // not after a newline
  EXPECT_TRUE(mid_line.restarted);
  EXPECT_EQ(mid_line.rows.size(), 1u);
}

TEST_F(CsvSliceTest, MalformedLinesAreReportedNotFatal) {
  const fs::path file = write("t,r\n1,10\n2\n3,abc\n4,40,5\n5,50\n");
  const CsvSlice slice = read_csv_slice(file, 0);
  ASSERT_EQ(slice.rows.size(), 3u);  // lines 2, 4 (with a NaN) and 6
  EXPECT_EQ(slice.rows[1][0], 3);
  EXPECT_TRUE(std::isnan(slice.rows[1][1]));
  EXPECT_EQ(slice.rows[2], (std::vector<double>{5, 50}));
  ASSERT_EQ(slice.problems.size(), 3u);
  EXPECT_EQ(slice.problems[0], "line 3: 1 cells, the header has 2");
  EXPECT_EQ(slice.problems[1], "line 4: 'abc' in column r is not a number");
  EXPECT_EQ(slice.problems[2], "line 5: 3 cells, the header has 2");
}

TEST_F(CsvSliceTest, AFileWithoutACompleteHeaderHasNoColumnsYet) {
  const CsvSlice empty = read_csv_slice(write(""), 0);
  EXPECT_TRUE(empty.columns.empty());
  EXPECT_FALSE(empty.partial_line);
  const CsvSlice half = read_csv_slice(write("time/total_time"), 0);
  EXPECT_TRUE(half.columns.empty());
  EXPECT_TRUE(half.partial_line);
  EXPECT_EQ(half.next_offset, 0u);
}

TEST_F(CsvSliceTest, MissingAndOversizedFilesAreErrors) {
  EXPECT_NE(testing::error_message([&] {
              read_csv_slice(directory_ / "none.csv", 0);
            }).find("cannot read"),
            std::string::npos);
  const fs::path file = write("t\n1\n2\n");
  EXPECT_NE(testing::error_message([&] { read_csv_slice(file, 0, 4); }).find("too large"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::dashboard
