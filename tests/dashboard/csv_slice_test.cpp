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

// A slice reads a page of lines and lists the first problems with a count of all: a long
// malformed file gives answers of bounded size, and the pages together give every row once.
TEST_F(CsvSliceTest, LongFilesComeInPagesWithTheFirstProblemsListed) {
  std::string text = "t,r\n";
  for (int i = 0; i < 1000; ++i) {
    text += std::to_string(i) + "," + std::to_string(2 * i) + "\n";
    if (i % 4 == 0) text += "bad line\n";
    if (i % 10 == 0) text += "\n";
  }
  const fs::path file = write(text);
  const CsvSliceLimits limits{.max_lines = 300, .max_problems = 7};
  std::vector<std::vector<double>> rows;
  int64_t problems = 0;
  uint64_t offset = 0;
  int pages = 0;
  while (true) {
    const CsvSlice slice = read_csv_slice(file, offset, limits);
    ++pages;
    EXPECT_LE(slice.problems.size(), 7u);
    EXPECT_LE(slice.rows.size() + static_cast<std::size_t>(slice.problem_count), 300u);
    if (slice.problem_count > 0) {
      EXPECT_EQ(slice.problems.size(), std::min<std::size_t>(7, slice.problem_count));
    }
    EXPECT_FALSE(slice.restarted);
    rows.insert(rows.end(), slice.rows.begin(), slice.rows.end());
    problems += slice.problem_count;
    offset = slice.next_offset;
    if (!slice.more) break;
    ASSERT_LT(pages, 20);
  }
  EXPECT_EQ(pages, 5);  // 1,000 rows + 250 malformed + 100 blank lines, 300 per page
  EXPECT_EQ(problems, 250);
  ASSERT_EQ(rows.size(), 1000u);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(rows[i], (std::vector<double>{1.0 * i, 2.0 * i}));
  EXPECT_EQ(offset, text.size());
}

TEST_F(CsvSliceTest, MissingAndOversizedFilesAreErrors) {
  EXPECT_NE(testing::error_message([&] {
              read_csv_slice(directory_ / "none.csv", 0);
            }).find("cannot read"),
            std::string::npos);
  const fs::path file = write("t\n1\n2\n");
  EXPECT_NE(
      testing::error_message([&] { read_csv_slice(file, 0, {.max_bytes = 4}); }).find("too large"),
      std::string::npos);
  std::string wide = "c0";
  for (int i = 1; i <= 10000; ++i) wide += ",c" + std::to_string(i);
  EXPECT_NE(
      testing::error_message([&] { read_csv_slice(write(wide + "\n"), 0); }).find("10001 columns"),
      std::string::npos);
}

}  // namespace
}  // namespace tendril::dashboard
