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
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

  // A valid file without pressures of two rows, whose lines tests then break.
  static std::string valid_text() {
    std::string text = std::string(kPneumaticDatasetTitle) + "\n# robot: twin\n";
    const auto names = pneumatic_dataset_columns(false);
    for (size_t i = 0; i < names.size(); ++i) text += (i ? "," : "") + names[i];
    text += "\n0,1,1,1,1,1,1,1,1,1,0,0,-199,0,0,-398,0,0,-598\n";
    text += "0.1,1,1,1,1,1,1,1,1,1,0,0,-199,0,0,-398,0,0,-598.5\n";
    return text;
  }
};

TEST_F(PneumaticDatasetFile, RoundTripsExactlyWithAndWithoutPressures) {
  for (bool with_pressures : {true, false}) {
    const PneumaticDataset data = random_dataset(50, with_pressures);
    const auto file = directory_ / (with_pressures ? "with.csv" : "without.csv");
    write_pneumatic_dataset(file, data);
    const PneumaticDataset back = read_pneumatic_dataset(file);
    EXPECT_EQ(back.metadata, data.metadata);
    EXPECT_EQ(back.time_s, data.time_s);
    EXPECT_EQ(back.commands_bar, data.commands_bar);
    EXPECT_EQ(back.pressures_bar, data.pressures_bar);
    EXPECT_EQ(back.tips_mm, data.tips_mm);
    EXPECT_EQ(back.has_pressures(), with_pressures);
    EXPECT_EQ(back.meta("robot"), "PneumaticArm/Robot-v0");
    EXPECT_FALSE(back.meta("absent").has_value());
  }
  // Windows line ends read the same.
  std::string text = valid_text();
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(read_pneumatic_dataset(write_text("crlf.csv", crlf)).tips_mm,
            read_pneumatic_dataset(write_text("lf.csv", text)).tips_mm);
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
  PneumaticDataset bad = data;
  bad.tips_mm(2, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_message([&] { write_pneumatic_dataset(fresh, bad); }).find("finite"),
            std::string::npos);
  bad = data;
  bad.time_s[3] = bad.time_s[2];
  EXPECT_NE(error_message([&] { write_pneumatic_dataset(fresh, bad); }).find("increase"),
            std::string::npos);
  bad = data;
  bad.commands_bar.conservativeResize(4, 9);
  EXPECT_NE(error_message([&] { write_pneumatic_dataset(fresh, bad); }).find("same number"),
            std::string::npos);
  bad = data;
  bad.metadata.emplace_back("two\nlines", "x");
  EXPECT_NE(error_message([&] { write_pneumatic_dataset(fresh, bad); }).find("metadata key"),
            std::string::npos);
  bad = data;
  bad.metadata.emplace_back("key", "two\nlines");
  EXPECT_NE(error_message([&] { write_pneumatic_dataset(fresh, bad); }).find("one line"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(fresh));
}

// Each malformed file names the file and the line at fault.
TEST_F(PneumaticDatasetFile, MalformedFilesAreNamedByFileAndLine) {
  const auto replace_line = [](std::string text, int line, const std::string& with) {
    std::istringstream in(text);
    std::string result, current;
    for (int n = 1; std::getline(in, current); ++n) result += (n == line ? with : current) + "\n";
    return result;
  };
  const std::string good = valid_text();
  struct Case {
    std::string name, text, expected;
  };
  const std::vector<Case> cases = {
      {"title.csv", replace_line(good, 1, "# some other file"), ":1: the first line"},
      {"meta.csv", replace_line(good, 2, "# no colon here"), ":2: metadata lines"},
      {"header.csv", replace_line(good, 3, "time_s,tip_x"), ":3: the header"},
      {"fields.csv", replace_line(good, 5, "0.1,1,1,1"), ":5: expected 19 fields, got 4"},
      {"number.csv", replace_line(good, 4, "0,1,1,1,1,1,1,1,1,1,0,0,-199,0,0,-398,0,0,x"),
       ":4: column tip_m3_z_mm: 'x' is not a finite number"},
      {"nan.csv", replace_line(good, 4, "0,1,1,1,1,nan,1,1,1,1,0,0,-199,0,0,-398,0,0,-598"),
       ":4: column command_m2_c2_bar: 'nan'"},
      {"blank.csv", replace_line(good, 4, "0,1,1,1,1,,1,1,1,1,0,0,-199,0,0,-398,0,0,-598"),
       ":4: column command_m2_c2_bar: ''"},
      {"time.csv", replace_line(good, 5, "0,1,1,1,1,1,1,1,1,1,0,0,-199,0,0,-398,0,0,-598"),
       ":5: time_s must increase"},
      {"rows.csv", good.substr(0, good.find('\n', good.find("time_s")) + 1),
       ":3: the data set has no rows"},
      {"empty.csv", "", ":1: the first line"},
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
