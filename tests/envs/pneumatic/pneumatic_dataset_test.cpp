#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::envs::pneumatic {
namespace {

using testing::error_message;

class PneumaticDatasetFile : public testing::ScratchDirectoryTest {
 protected:
  PneumaticDatasetFile() : ScratchDirectoryTest("pneumatic_dataset") {}

  static PneumaticDataset random_dataset(int rows, bool with_pressures) {
    Rng rng(17);
    PneumaticDataset data;
    data.metadata = {{"robot", "PneumaticArm/Robot-v0"},
                     {"note", "values: a, b; c"},
                     {"rows", std::to_string(rows)},
                     {"config", "  params: {scenario: S1}"},
                     {"config", "seed: 3"}};
    data.time_s.resize(rows);
    data.commands_bar.resize(rows, 9);
    data.tips_mm.resize(rows, 9);
    if (with_pressures) data.pressures_bar.resize(rows, 9);
    for (int k = 0; k < rows; ++k) {
      data.time_s[k] = 0.1 * k + rng.uniform(0.0, 0.01);
      for (int c = 0; c < 9; ++c) {
        data.commands_bar(k, c) = rng.uniform(0.0, 1.5);
        data.tips_mm(k, c) = rng.normal(-300.0, 200.0) * std::pow(10.0, rng.uniform(-8.0, 3.0));
        if (with_pressures) data.pressures_bar(k, c) = rng.uniform(0.0, 1.5);
      }
    }
    return data;
  }

  std::filesystem::path write_text(const std::string& name, const std::string& text) {
    const std::filesystem::path file = directory_ / name;
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    return file;
  }

  static std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  // The text of a written data set without its checksum line, which tests then edit (a data set
  // without one is read as it is, as one written by other software).
  std::string unchecked_text(const PneumaticDataset& data, const std::string& name) {
    const auto file = directory_ / name;
    write_pneumatic_dataset(file, data);
    std::string text = read_text(file);
    const std::size_t begin = text.find("# crc32c: ");
    text.erase(begin, text.find('\n', begin) + 1 - begin);
    return text;
  }

  static void expect_equal(const PneumaticDataset& a, const PneumaticDataset& b) {
    EXPECT_EQ(a.metadata, b.metadata);
    EXPECT_EQ(a.time_s, b.time_s);
    EXPECT_EQ(a.commands_bar, b.commands_bar);
    EXPECT_EQ(a.pressures_bar, b.pressures_bar);
    EXPECT_EQ(a.tips_mm, b.tips_mm);
  }
};

// The 1-based number of the line of `text` holding `part`.
int line_of(const std::string& text, const std::string& part) {
  const std::size_t at = text.find(part);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

std::string replace_line(const std::string& text, int line, const std::string& with) {
  std::istringstream in(text);
  std::string result, current;
  for (int n = 1; std::getline(in, current); ++n) result += (n == line ? with : current) + "\n";
  return result;
}

TEST_F(PneumaticDatasetFile, RoundTripsExactlyWithAndWithoutPressures) {
  for (bool with_pressures : {true, false}) {
    const PneumaticDataset data = random_dataset(50, with_pressures);
    const auto file = directory_ / (with_pressures ? "with.csv" : "without.csv");
    write_pneumatic_dataset(file, data);
    const PneumaticDataset back = read_pneumatic_dataset(file);
    expect_equal(back, data);
    EXPECT_EQ(back.has_pressures(), with_pressures);
    EXPECT_EQ(back.meta("robot"), "PneumaticArm/Robot-v0");
    EXPECT_FALSE(back.meta("absent").has_value());
    // The one data-set format: format line, documented columns, checksum, then plain CSV.
    const std::string text = read_text(file);
    EXPECT_EQ(text.rfind(with_pressures
                             ? "# format: tendril.pneumatic_arm.data_set v2\n"
                             : "# format: tendril.pneumatic_arm.data_set_without_pressures v2\n",
                         0),
              0u);
    EXPECT_NE(text.find("\n# column tip_m3_z_mm: mm, tip of module 3"), std::string::npos);
    EXPECT_NE(text.find("\n# crc32c: "), std::string::npos);
    EXPECT_EQ(pneumatic_dataset_columns(with_pressures).size(), with_pressures ? 28u : 19u);
  }
}

TEST_F(PneumaticDatasetFile, TheWriterRefusesToOverwriteOrToWriteBadData) {
  const auto file = directory_ / "data.csv";
  PneumaticDataset data = random_dataset(5, true);
  write_pneumatic_dataset(file, data);
  const auto before = std::filesystem::file_size(file);
  EXPECT_NE(error_message([&] {
              write_pneumatic_dataset(file, random_dataset(3, false));
            }).find("exists"),
            std::string::npos);
  EXPECT_EQ(std::filesystem::file_size(file), before);

  const auto fresh = directory_ / "fresh.csv";
  const auto refusal = [&](const PneumaticDataset& bad) {
    return error_message([&] { write_pneumatic_dataset(fresh, bad); });
  };
  PneumaticDataset bad = data;
  bad.tips_mm(2, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refusal(bad).find("finite"), std::string::npos);
  bad = data;
  bad.time_s[3] = bad.time_s[2];
  EXPECT_NE(refusal(bad).find(", row 3: time_s must increase"), std::string::npos);
  bad = data;
  bad.commands_bar.conservativeResize(4, 9);
  EXPECT_NE(refusal(bad).find("same number"), std::string::npos);
  bad = data;
  bad.commands_bar(1, 4) = 1.6;
  EXPECT_NE(refusal(bad).find(", row 1: column command_m2_c2_bar: 1.6 bar lies outside [0, 1.5]"),
            std::string::npos)
      << refusal(bad);
  bad.metadata.emplace_back("command_ceiling_bar", "2");
  write_pneumatic_dataset(directory_ / "higher.csv", bad);  // a regulator of another range
  EXPECT_EQ(read_pneumatic_dataset(directory_ / "higher.csv").commands_bar(1, 4), 1.6);
  bad = data;
  bad.metadata[2].second = "6";
  EXPECT_NE(refusal(bad).find("rows: 6, it holds 5"), std::string::npos);
  bad = data;
  bad.metadata.emplace_back("two\nlines", "x");
  EXPECT_NE(refusal(bad).find("metadata key"), std::string::npos);
  bad = data;
  bad.metadata.emplace_back("key", "two\nlines");
  EXPECT_NE(refusal(bad).find("one line"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(fresh));
}

// What a recording suffers in transit or on a disk is refused, never read as data — with the
// checksum the file carries, and by the rows' own checks when that line was deleted.
TEST_F(PneumaticDatasetFile, DamagedOrCutFilesAreRefused) {
  const PneumaticDataset data = random_dataset(40, true);
  const auto file = directory_ / "twin.csv";
  write_pneumatic_dataset(file, data);
  const std::string text = read_text(file);
  const std::string plain = unchecked_text(data, "plain.csv");
  expect_equal(read_pneumatic_dataset(write_text("plain_copy.csv", plain)), data);

  // A command of 0.x bar turned into 9.x bar (one digit).
  const std::size_t header = plain.find("\ntime_s,") + 1;
  const std::size_t row = plain.find('\n', plain.find('\n', header) + 1) + 1;  // the 2nd row
  const std::size_t digit = plain.find(",0.", row) + 1;
  ASSERT_LT(digit, plain.find('\n', row));
  for (const bool checked : {true, false}) {
    std::string changed = checked ? text : plain;
    const std::size_t at = checked ? digit + (text.size() - plain.size()) : digit;
    ASSERT_EQ(changed[at], '0');
    changed[at] = '9';
    const auto damaged = write_text(checked ? "digit_checked.csv" : "digit.csv", changed);
    const std::string message = error_message([&] { read_pneumatic_dataset(damaged); });
    const int line = 1 + static_cast<int>(std::count(
                             changed.begin(), changed.begin() + static_cast<long>(at), '\n'));
    EXPECT_NE(message.find(damaged.string() + ":" +
                           (checked ? std::to_string(line_of(changed, "# crc32c")) + ": corrupt"
                                    : std::to_string(line) + ": column command_m")),
              std::string::npos)
        << message;
    if (!checked) EXPECT_NE(message.find("lies outside [0, 1.5]"), std::string::npos) << message;
  }
  // Cut to half its rows at a line end: the checksum, or without it the `rows` line, says so.
  const std::size_t half = text.find('\n', text.find("\ntime_s,") + text.size() / 2) + 1;
  EXPECT_NE(error_message([&] {
              read_pneumatic_dataset(write_text("half_checked.csv", text.substr(0, half)));
            }).find("corrupt"),
            std::string::npos);
  const std::size_t plain_half = plain.find('\n', plain.find("\ntime_s,") + plain.size() / 2) + 1;
  const std::string message = error_message(
      [&] { read_pneumatic_dataset(write_text("half.csv", plain.substr(0, plain_half))); });
  EXPECT_NE(message.find("its header says rows: 40, it holds "), std::string::npos) << message;
  // Cut inside the last number.
  for (const std::string& whole : {text, plain}) {
    const std::string cut_message = error_message(
        [&] { read_pneumatic_dataset(write_text("cut.csv", whole.substr(0, whole.size() - 4))); });
    EXPECT_NE(cut_message.find("cut short"), std::string::npos) << cut_message;
  }
  // The earlier format, without a checksum.
  const auto old = write_text("old.csv", "# tendril pneumatic-arm data set v1\n# robot: twin\n");
  EXPECT_NE(error_message([&] {
              read_pneumatic_dataset(old);
            }).find(old.string() + ":1: a data set of the earlier format"),
            std::string::npos);
}

// Any single bit flipped anywhere in a data set: refused, or (a flip that only renames the
// checksum line, which then reads as metadata) the numbers read back unchanged.
TEST_F(PneumaticDatasetFile, EveryFlippedBitIsRefusedOrChangesNoNumber) {
  const PneumaticDataset data = random_dataset(6, false);
  const auto file = directory_ / "small.csv";
  write_pneumatic_dataset(file, data);
  const std::string text = read_text(file);
  Rng rng(5);
  int refused = 0, unchanged = 0;
  for (std::size_t position = 0; position < text.size(); position += 3) {
    std::string flipped = text;
    flipped[position] = static_cast<char>(flipped[position] ^ (1 << rng.below(8)));
    const auto damaged = write_text("flipped.csv", flipped);
    try {
      const PneumaticDataset read = read_pneumatic_dataset(damaged);
      EXPECT_EQ(read.time_s, data.time_s) << position;
      EXPECT_EQ(read.commands_bar, data.commands_bar) << position;
      EXPECT_EQ(read.tips_mm, data.tips_mm) << position;
      ++unchanged;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(damaged.string()), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, 400);
  EXPECT_LE(unchanged, 4);
}

// Each malformed file names the file and the line at fault.
TEST_F(PneumaticDatasetFile, MalformedFilesAreNamedByFileAndLine) {
  PneumaticDataset small = random_dataset(2, false);
  small.metadata = {{"robot", "twin"}};
  const std::string good = unchecked_text(small, "good.csv");
  const int header = line_of(good, "\ntime_s,") + 1;
  struct Case {
    std::string name, text, expected;
  };
  const std::vector<Case> cases = {
      {"format.csv", replace_line(good, 1, "# some other file"),
       ":1: expected '# format: tendril.pneumatic_arm.data_set v2'"},
      {"meta.csv", replace_line(good, header - 1, "# no colon here"),
       ":" + std::to_string(header - 1) + ": a header comment must read '# key: value'"},
      {"header.csv", replace_line(good, header, "time_s,tip_x"),
       ":" + std::to_string(header) + ": expected the column header 'time_s,command_m1_c1_bar,"},
      {"fields.csv", replace_line(good, header + 2, "0.1,1,1,1"),
       ":" + std::to_string(header + 2) + ": expected 19 fields, got 4"},
      {"number.csv", replace_line(good, header + 1, "0,1,1,1,1,1,1,1,1,1,0,0,-199,0,0,-398,0,0,x"),
       ":" + std::to_string(header + 1) + ": column tip_m3_z_mm: 'x' is not a number"},
      {"nan.csv", replace_line(good, header + 1, "0,1,1,1,1,nan,1,1,1,1,0,0,-199,0,0,-398,0,0,1"),
       ":" + std::to_string(header + 1) + ": column command_m2_c2_bar: 'nan' is not finite"},
      {"time.csv",
       replace_line(good, header + 2, "-1,1,1,1,1,1,1,1,1,1,0,0,-199,0,0,-398,0,0,-598"),
       ":" + std::to_string(header + 2) + ": time_s must increase"},
      {"negative.csv",
       replace_line(good, header + 2, "9,1,1,1,1,-0.5,1,1,1,1,0,0,-199,0,0,-398,0,0,-598"),
       ":" + std::to_string(header + 2) + ": column command_m2_c2_bar: -0.5 bar lies outside"},
      {"rows.csv", good.substr(0, good.find('\n', good.find("\ntime_s") + 1) + 1),
       ": the data set has no rows"},
      {"empty.csv", "", ":1: empty data file"},
  };
  for (const Case& c : cases) {
    const auto file = write_text(c.name, c.text);
    const std::string message = error_message([&] { read_pneumatic_dataset(file); });
    EXPECT_NE(message.find(file.string() + c.expected), std::string::npos)
        << c.name << ": " << message;
  }
  EXPECT_NE(error_message([&] {
              read_pneumatic_dataset(directory_ / "missing.csv");
            }).find("cannot open"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::envs::pneumatic
