#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/pneumatic/decimal_text.hpp"

namespace tendril::envs::pneumatic {

namespace {

namespace fs = std::filesystem;

std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  while (true) {
    const size_t end = line.find(separator, start);
    fields.push_back(line.substr(start, end == std::string_view::npos ? end : end - start));
    if (end == std::string_view::npos) return fields;
    start = end + 1;
  }
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

std::string join(const std::vector<std::string>& names) {
  std::string line;
  for (size_t i = 0; i < names.size(); ++i) line += (i ? "," : "") + names[i];
  return line;
}

}  // namespace

std::optional<std::string> PneumaticDataset::meta(std::string_view key) const {
  for (const auto& [name, value] : metadata) {
    if (name == key) return value;
  }
  return std::nullopt;
}

std::vector<std::string> pneumatic_dataset_columns(bool with_pressures) {
  std::vector<std::string> names{"time_s"};
  const auto chambers = [&](const std::string& quantity) {
    for (int m = 1; m <= 3; ++m) {
      for (int c = 1; c <= 3; ++c) {
        names.push_back(quantity + "_m" + std::to_string(m) + "_c" + std::to_string(c) + "_bar");
      }
    }
  };
  chambers("command");
  if (with_pressures) chambers("pressure");
  for (int m = 1; m <= 3; ++m) {
    for (const char* axis : {"x", "y", "z"}) {
      names.push_back("tip_m" + std::to_string(m) + "_" + axis + "_mm");
    }
  }
  return names;
}

void write_pneumatic_dataset(const fs::path& file, const PneumaticDataset& data) {
  const std::string where = file.string();
  const Eigen::Index rows = data.time_s.size();
  require(rows > 0, "a data set needs at least one row", where);
  require(data.commands_bar.rows() == rows && data.tips_mm.rows() == rows &&
              (data.pressures_bar.rows() == 0 || data.pressures_bar.rows() == rows),
          "time, commands, pressures and tips must have the same number of rows", where);
  require(data.time_s.allFinite() && data.commands_bar.allFinite() &&
              data.pressures_bar.allFinite() && data.tips_mm.allFinite(),
          "every value must be finite", where);
  for (Eigen::Index k = 1; k < rows; ++k) {
    require(data.time_s[k] > data.time_s[k - 1], "times must increase", where);
  }
  for (const auto& [key, value] : data.metadata) {
    require(!key.empty() && key.find_first_of(":\n\r") == std::string::npos && trim(key) == key,
            "metadata key '" + key + "' must be non-empty without ':', line breaks or edge spaces",
            where);
    require(value.find_first_of("\n\r") == std::string::npos,
            "metadata value of '" + key + "' must be one line", where);
  }
  require(!fs::exists(file), "the data set file exists; nothing was overwritten", where);

  std::string text = std::string(kPneumaticDatasetTitle) + "\n";
  for (const auto& [key, value] : data.metadata) text += "# " + key + ": " + value + "\n";
  text += join(pneumatic_dataset_columns(data.has_pressures())) + "\n";
  const auto append_row = [&](const PneumaticDataset::Columns& columns, Eigen::Index k) {
    for (int c = 0; c < 9; ++c) {
      text += ',';
      text += shortest_text(columns(k, c));
    }
  };
  for (Eigen::Index k = 0; k < rows; ++k) {
    text += shortest_text(data.time_s[k]);
    append_row(data.commands_bar, k);
    if (data.has_pressures()) append_row(data.pressures_bar, k);
    append_row(data.tips_mm, k);
    text += '\n';
  }
  if (!file.parent_path().empty()) fs::create_directories(file.parent_path());
  write_file_atomically(file, text, "data set");
}

PneumaticDataset read_pneumatic_dataset(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot open the data set file", file.string());
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();

  int line_number = 0;
  const auto fail = [&](const std::string& what) -> Error {
    return Error(what, file.string() + ":" + std::to_string(line_number));
  };
  std::vector<std::string_view> lines = split(text, '\n');
  if (!lines.empty() && lines.back().empty()) lines.pop_back();  // the final newline
  for (std::string_view& line : lines) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  }

  PneumaticDataset data;
  size_t index = 0;
  line_number = 1;
  if (lines.empty() || lines[0] != kPneumaticDatasetTitle) {
    throw fail("the first line must be '" + std::string(kPneumaticDatasetTitle) + "'");
  }
  for (index = 1; index < lines.size() && !lines[index].empty() && lines[index][0] == '#';
       ++index) {
    line_number = static_cast<int>(index) + 1;
    // "# key: value": the key up to the first ':', the value verbatim after ": ".
    const std::string_view body = lines[index].substr(1);
    const size_t colon = body.find(':');
    const std::string_view key =
        colon == std::string_view::npos ? std::string_view() : body.substr(1, colon - 1);
    if (body.empty() || body[0] != ' ' || key.empty() || trim(key) != key) {
      throw fail("metadata lines must read '# key: value'");
    }
    std::string_view value = body.substr(colon + 1);
    if (!value.empty() && value[0] == ' ') value.remove_prefix(1);
    data.metadata.emplace_back(std::string(key), std::string(value));
  }
  line_number = static_cast<int>(index) + 1;
  if (index >= lines.size()) throw fail("the header line of column names is missing");
  bool with_pressures = false;
  if (lines[index] == join(pneumatic_dataset_columns(true))) {
    with_pressures = true;
  } else if (lines[index] != join(pneumatic_dataset_columns(false))) {
    throw fail("the header must list the columns " + join(pneumatic_dataset_columns(false)) +
               " (with the pressure_m*_c*_bar columns after the commands, or without them)");
  }
  const int width = with_pressures ? 28 : 19;
  const size_t first_row = index + 1;
  const Eigen::Index rows = static_cast<Eigen::Index>(lines.size() - first_row);
  if (rows == 0) throw fail("the data set has no rows");
  data.time_s.resize(rows);
  data.commands_bar.resize(rows, 9);
  data.tips_mm.resize(rows, 9);
  if (with_pressures) data.pressures_bar.resize(rows, 9);

  const std::vector<std::string> names = pneumatic_dataset_columns(with_pressures);
  std::vector<double> values(width);
  for (Eigen::Index k = 0; k < rows; ++k) {
    line_number = static_cast<int>(first_row + k) + 1;
    const std::vector<std::string_view> fields = split(lines[first_row + k], ',');
    if (static_cast<int>(fields.size()) != width) {
      throw fail("expected " + std::to_string(width) + " fields, got " +
                 std::to_string(fields.size()));
    }
    for (int c = 0; c < width; ++c) {
      const std::string_view field = fields[c];
      double value = 0.0;
      const auto result = std::from_chars(field.data(), field.data() + field.size(), value);
      if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size() ||
          !std::isfinite(value)) {
        throw fail("column " + names[c] + ": '" + std::string(field) + "' is not a finite number");
      }
      values[c] = value;
    }
    if (k > 0 && !(values[0] > data.time_s[k - 1])) {
      throw fail("time_s must increase from row to row");
    }
    data.time_s[k] = values[0];
    for (int c = 0; c < 9; ++c) {
      data.commands_bar(k, c) = values[1 + c];
      if (with_pressures) data.pressures_bar(k, c) = values[10 + c];
      data.tips_mm(k, c) = values[width - 9 + c];
    }
  }
  return data;
}

}  // namespace tendril::envs::pneumatic
