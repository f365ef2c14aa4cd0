#include "tendril/dynamics/prepared_csv.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "synthetic_limb.hpp"

namespace tendril::dynamics {
namespace {

using testing::error_message;

class PreparedCsv : public testing::ScratchDirectoryTest {
 protected:
  PreparedCsv() : ScratchDirectoryTest("prepared_csv") {}

  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto file = directory_ / name;
    std::ofstream(file) << text;
    return file;
  }
};

constexpr const char* kHeader = "time_s,theta_x,theta_y,omega_x,omega_y,u_x,u_y,split\n";

TEST_F(PreparedCsv, ReadsTheSmaLimbLayout) {
  const auto file = write("limb.csv", std::string(kHeader) +
                                          "0,1.5,-2,10,-20,3,-4,train\n"
                                          "0.07,1.6,-2.1,1.4285714285714286,-1,3,-4,test\n");
  const SequenceData data = read_prepared_csv(file);
  ASSERT_EQ(data.rows(), 2);
  EXPECT_EQ(data.time(1), 0.07);
  EXPECT_EQ(data.states.row(0), Eigen::RowVector4d(1.5, -2, 10, -20));
  EXPECT_EQ(data.states(1, 2), 1.4285714285714286);
  EXPECT_EQ(data.inputs.row(1), Eigen::RowVector2d(3, -4));
  EXPECT_EQ(data.split[0], Split::kTrain);
  EXPECT_EQ(data.split[1], Split::kTest);
  EXPECT_EQ(data.state_names[3], "omega_y");
}

TEST_F(PreparedCsv, ReadsNamedColumnsInAnyOrderAndIgnoresOthers) {
  const auto file = write("arm.csv",
                          "split,p1,extra,x1,time_s\n"
                          "train,0.5,zzz,12,0\n"
                          "train,0.25,zzz,13,0.1\n");
  const SequenceData data = read_prepared_csv(file, CsvColumns{{"x1"}, {"p1"}});
  EXPECT_EQ(data.states(1, 0), 13);
  EXPECT_EQ(data.inputs(0, 0), 0.5);
}

TEST_F(PreparedCsv, AWrittenFileChangedLaterIsRefused) {
  const SequenceData data = testing::SyntheticLimb{}.generate(20, 1);
  const auto file = directory_ / "checked.csv";
  write_prepared_csv(data, file);
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(text.rfind("# crc32c: ", 0), 0u);
  text[text.rfind(",train")] = ';';  // one changed byte in the last row
  const auto changed = write("changed.csv", text);
  EXPECT_NE(error_message([&] { read_prepared_csv(changed); }).find("corrupt: its CRC-32C"),
            std::string::npos);
}

// Changed line ends get a message saying so, naming the file and line.
TEST_F(PreparedCsv, ChangedLineEndsAreNamed) {
  const SequenceData data = testing::SyntheticLimb{}.generate(20, 1);
  const auto file = directory_ / "written.csv";
  write_prepared_csv(data, file);
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string crlf, cr;
  for (char c : text) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    cr += c == '\n' ? '\r' : c;
  }
  std::ofstream(directory_ / "crlf.csv", std::ios::binary) << crlf;
  std::ofstream(directory_ / "cr.csv", std::ios::binary) << cr;
  EXPECT_NE(error_message([&] {
              read_prepared_csv(directory_ / "crlf.csv");
            }).find((directory_ / "crlf.csv").string() + ":1: its line ends were changed to CRLF"),
            std::string::npos);
  EXPECT_NE(
      error_message([&] {
        read_prepared_csv(directory_ / "cr.csv");
      }).find((directory_ / "cr.csv").string() + ":1: its lines end in a carriage return alone"),
      std::string::npos);
  // Rows remember their lines (blank lines skipped) for later messages.
  const auto spaced = write(
      "spaced.csv", std::string(kHeader) + "0,1,2,3,4,5,6,train\n\n" + "0.1,1,2,3,4,5,6,test\n");
  const SequenceData read = read_prepared_csv(spaced);
  EXPECT_EQ(read.lines, (std::vector<int64_t>{2, 4}));
  EXPECT_EQ(read.where(1), spaced.string() + ":4");
}

TEST_F(PreparedCsv, WriteThenReadIsExact) {
  const SequenceData data = testing::SyntheticLimb{}.generate(50, 3);
  const auto file = directory_ / "synthetic.csv";
  write_prepared_csv(data, file);
  const SequenceData back = read_prepared_csv(file);
  EXPECT_EQ(back.time, data.time);
  EXPECT_EQ(back.states, data.states);
  EXPECT_EQ(back.inputs, data.inputs);
  EXPECT_EQ(back.split, data.split);
}

TEST_F(PreparedCsv, WritingNeverOverwrites) {
  const SequenceData data = testing::SyntheticLimb{}.generate(5, 3);
  const auto file = write("taken.csv", "keep me\n");
  EXPECT_NE(error_message([&] { write_prepared_csv(data, file); }).find("nothing is overwritten"),
            std::string::npos);
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "keep me");
}

TEST_F(PreparedCsv, BadFilesNameTheFileLineAndColumn) {
  const auto missing_column = write("a.csv", "time_s,theta_x,split\n0,1,train\n");
  EXPECT_NE(error_message([&] { read_prepared_csv(missing_column); }).find("no column 'theta_y'"),
            std::string::npos);
  const auto truncated = write("b.csv", std::string(kHeader) + "0,1,2,3,4,5,6,train\n0.07,1,2\n");
  const std::string message = error_message([&] { read_prepared_csv(truncated); });
  EXPECT_NE(message.find("b.csv:3"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
  const auto not_a_number = write("c.csv", std::string(kHeader) + "0,1,2,x3,4,5,6,train\n");
  const std::string bad_number = error_message([&] { read_prepared_csv(not_a_number); });
  EXPECT_NE(bad_number.find("c.csv:2"), std::string::npos) << bad_number;
  EXPECT_NE(bad_number.find("omega_x"), std::string::npos) << bad_number;
  const auto nan = write("d.csv", std::string(kHeader) + "0,1,2,nan,4,5,6,train\n");
  EXPECT_NE(error_message([&] { read_prepared_csv(nan); }).find("not a finite number"),
            std::string::npos);
  const auto bad_split = write("e.csv", std::string(kHeader) + "0,1,2,3,4,5,6,validate\n");
  EXPECT_NE(error_message([&] { read_prepared_csv(bad_split); }).find("neither train nor test"),
            std::string::npos);
  const auto empty = write("f.csv", "");
  EXPECT_NE(error_message([&] { read_prepared_csv(empty); }).find("empty"), std::string::npos);
  const auto header_only = write("g.csv", kHeader);
  EXPECT_NE(error_message([&] { read_prepared_csv(header_only); }).find("no rows"),
            std::string::npos);
  EXPECT_NE(
      error_message([&] { read_prepared_csv(directory_ / "absent.csv"); }).find("cannot open"),
      std::string::npos);
}

TEST(SequenceData, SegmentsBreakAtGapsStepsBackAndSplitChanges) {
  SequenceData data = testing::SyntheticLimb{}.generate(10, 1);
  data.time << 0, 0.1, 0.2, 0.9, 1.0, 1.1, 0.5, 0.6, 0.7, 0.8;
  for (int t = 0; t < 10; ++t) data.split[t] = t < 8 ? Split::kTrain : Split::kTest;
  const std::vector<Segment> segments = data.segments(0.5);
  ASSERT_EQ(segments.size(), 4u);
  EXPECT_EQ(segments[0].begin, 0);
  EXPECT_EQ(segments[0].end, 3);  // 0.2 → 0.9 is a gap
  EXPECT_EQ(segments[1].end, 6);  // 1.1 → 0.5 steps back
  EXPECT_EQ(segments[2].end, 8);  // the test split starts at row 8
  EXPECT_EQ(segments[3].split, Split::kTest);
  EXPECT_NEAR(data.sample_period(), 0.1, 1e-12);
}

}  // namespace
}  // namespace tendril::dynamics
