// Data files: exact round trips, and strict reading that names the file and line of any fault.
#include "tendril/core/data_table.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/crc32c.hpp"

namespace tendril::data {
namespace {

using tendril::testing::error_message;

const TableSchema& schema() {
  static const TableSchema s{"test.table v1",
                             {{"t", 3, {}, "time, s"},
                              {"angle", 2, {}, "an angle, deg"},
                              {"count", 0, {}, "an integer"},
                              {"kind", 0, {"train", "test"}, "which set"}}};
  return s;
}

class TableFile : public tendril::testing::ScratchDirectoryTest {
 protected:
  TableFile() : ScratchDirectoryTest("data_table") {}
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto file = directory_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  std::string read(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static constexpr const char* kGood =
      "# format: test.table v1\n"
      "# column t: time, s\n"
      "# column angle: an angle, deg\n"
      "# column count: an integer\n"
      "# column kind: which set\n"
      "# limb: stiff\n"
      "t,angle,count,kind\n"
      "0.000,-10.25,3,train\n"
      "0.061,0.00,-2,test\n";
};

TEST_F(TableFile, WritesTheDocumentedLayoutAndReadsItBackExactly) {
  Table table;
  table.set("limb", "stiff");
  table.values.resize(2, 4);
  table.values << 0.0, -10.25, 3, 0, 0.061, -0.0001, -2, 1;
  const auto file = directory_ / "table.csv";
  write_table(file, table, schema());
  // kGood with the checksum of all its bytes before the column names.
  std::string expected = kGood;
  const std::string checksum = checksum_text(crc32c(expected.data(), expected.size()));
  expected.insert(expected.find("t,angle"), "# crc32c: " + checksum + "\n");
  EXPECT_EQ(read(file), expected) << "−0.0001 is written 0.00, not -0.00";
  const Table back = read_table(file, schema());
  EXPECT_EQ(back.get("limb"), "stiff");
  ASSERT_EQ(back.rows(), 2);
  EXPECT_EQ(back.values(0, 1), -10.25);
  EXPECT_EQ(back.values(1, 0), 0.061);
  EXPECT_EQ(back.values(1, 2), -2);
  EXPECT_EQ(back.values(1, 3), 1);
  EXPECT_EQ(back.where(1), file.string() + ":10");
  EXPECT_EQ(back.metadata.size(), 1u) << "the checksum is not metadata";
  // Values at the written precision round-trip exactly.
  const auto again = directory_ / "again.csv";
  write_table(again, back, schema());
  EXPECT_EQ(read(again), read(file));
}

TEST_F(TableFile, AFileChangedAfterItWasWrittenIsRefusedAndOneWithoutAChecksumIsRead) {
  Table table;
  table.values.resize(1, 4);
  table.values << 0.5, 1.25, 7, 1;
  const auto file = directory_ / "checked.csv";
  write_table(file, table, schema());
  std::string text = read(file);
  const std::size_t digit = text.find("1.25");
  ASSERT_NE(digit, std::string::npos);
  text[digit] = '2';  // still a valid table: only the checksum can tell
  const auto changed = write("changed.csv", text);
  const std::string message = error_message([&] { read_table(changed, schema()); });
  EXPECT_NE(message.find(changed.string() + ":6: corrupt: its CRC-32C is"), std::string::npos)
      << message;
  EXPECT_EQ(read_table(write("unchecked.csv", kGood), schema()).rows(), 2);
}

// Line ends changed after writing: each gets a message that says so, at the file and line.
TEST_F(TableFile, ChangedLineEndsAreNamedNotReportedAsDamage) {
  Table table;
  table.values.resize(1, 4);
  table.values << 0.5, 1.25, 7, 1;
  const auto file = directory_ / "written.csv";
  write_table(file, table, schema());
  const std::string text = read(file);
  std::string crlf, cr;
  for (char c : text) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    cr += c == '\n' ? '\r' : c;
  }
  const auto windows = write("windows.csv", crlf);
  std::string message = error_message([&] { read_table(windows, schema()); });
  EXPECT_NE(message.find(windows.string() + ":6: its line ends were changed to CRLF"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find('\r'), std::string::npos) << "no invisible characters in the message";
  const auto mac = write("mac.csv", cr);
  message = error_message([&] { read_table(mac, schema()); });
  EXPECT_NE(message.find(mac.string() + ":1: its lines end in a carriage return alone"),
            std::string::npos)
      << message;
  // Without a checksum line, CRLF line ends are read as they are.
  EXPECT_EQ(read_table(write("crlf.csv",
                             [&] {
                               std::string out;
                               for (char c : std::string(kGood)) {
                                 out += c == '\n' ? std::string("\r\n") : std::string(1, c);
                               }
                               return out;
                             }()),
                       schema())
                .rows(),
            2);
}

// kShortest columns keep any double exactly, as the shortest text that reads back as it.
TEST_F(TableFile, ShortestColumnsRoundTripEveryDoubleExactly) {
  const TableSchema exact{"test.exact v1",
                          {{"t", ColumnSpec::kShortest, {}, "time, s"},
                           {"x", ColumnSpec::kShortest, {}, "a measurement"}}};
  Table table;
  table.values.resize(4, 2);
  table.values << 0.1 * 3, 1e-300, 0.7, -598.5, 123456.789012345678, 5e300, 3, -0.0;
  const auto file = directory_ / "exact.csv";
  write_table(file, table, exact);
  const std::string text = read(file);
  EXPECT_NE(text.find("\n0.30000000000000004,1e-300\n0.7,-598.5\n"), std::string::npos) << text;
  const Table back = read_table(file, exact);
  ASSERT_EQ(back.rows(), 4);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 2; ++c) EXPECT_EQ(back.values(r, c), table.values(r, c)) << r << c;
  }
  EXPECT_EQ(read_table_format(file), "test.exact v1");
  EXPECT_EQ(read_table_format(write("plain.csv", "t,x\n1,2\n")), "");
}

TEST_F(TableFile, NeverOverwritesAndRefusesValuesItCannotWrite) {
  const auto file = write("existing.csv", kGood);
  Table table = read_table(file, schema());
  EXPECT_NE(error_message([&] { write_table(file, table, schema()); }).find("already exists"),
            std::string::npos);
  EXPECT_EQ(read(file), kGood);
  table.values(1, 2) = 2.5;
  EXPECT_NE(error_message([&] {
              write_table(directory_ / "a.csv", table, schema());
            }).find("count is not an integer"),
            std::string::npos);
  table.values(1, 2) = 2;
  table.values(0, 1) = NAN;
  EXPECT_NE(
      error_message([&] { write_table(directory_ / "b.csv", table, schema()); }).find("row 0"),
      std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(directory_ / "a.csv"));
  EXPECT_FALSE(std::filesystem::exists(directory_ / "b.csv"));
}

// Each fault is reported with the file and the line it is on.
TEST_F(TableFile, MalformedFilesNameTheFileAndLine) {
  struct Case {
    std::string name, from, to, expected;
  };
  const std::vector<Case> cases{
      {"format", "test.table v1", "test.table v2", ":1: expected '# format: test.table v1'"},
      {"header", "t,angle,count,kind", "t,angle,kind,count", ":7: expected the column header"},
      {"fields", "0.061,0.00,-2,test", "0.061,0.00,-2", ":9: expected 4 fields, got 3"},
      {"number", "-10.25", "-10.2x", ":8: column angle: '-10.2x' is not a number"},
      {"empty", "-10.25", "", ":8: column angle: '' is not a number"},
      {"nan", "-10.25", "nan", ":8: column angle: 'nan' is not finite"},
      {"integer", ",-2,", ",-2.5,", ":9: column count: '-2.5' is not an integer"},
      {"word", ",test\n", ",valid\n", ":9: column kind: 'valid' is not one of its words"},
      {"comment", "# limb: stiff", "# limb stiff", ":6: a header comment must read"},
      {"crlf", "0.061,0.00,-2,test\n", "0.061,0.00,-2,test\r\n", "no error"},
  };
  for (const Case& c : cases) {
    std::string text = kGood;
    text.replace(text.find(c.from), c.from.size(), c.to);
    const auto file = write(c.name + ".csv", text);
    const std::string message = error_message([&] { read_table(file, schema()); });
    if (c.expected == "no error") {
      EXPECT_EQ(message, "no error") << c.name;
    } else {
      EXPECT_NE(message.find(file.string() + c.expected), std::string::npos)
          << c.name << ": " << message;
    }
  }
}

// A file cut short — mid-line, or without its header — is an error, never half a table.
TEST_F(TableFile, TruncatedFilesAreErrors) {
  const std::string text = kGood;
  const auto cut = write("cut.csv", text.substr(0, text.size() - 5));
  EXPECT_NE(error_message([&] {
              read_table(cut, schema());
            }).find(cut.string() + ":9: truncated: the last line has no line end"),
            std::string::npos);
  const auto headless = write("headless.csv", text.substr(0, text.find("t,angle")));
  EXPECT_NE(error_message([&] { read_table(headless, schema()); }).find("no column header"),
            std::string::npos);
  const auto empty = write("empty.csv", "");
  EXPECT_NE(error_message([&] { read_table(empty, schema()); }).find("empty data file"),
            std::string::npos);
  EXPECT_NE(
      error_message([&] { read_table(directory_ / "missing.csv", schema()); }).find("missing.csv"),
      std::string::npos);
}

}  // namespace
}  // namespace tendril::data
