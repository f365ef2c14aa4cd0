#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"

#include <charconv>
#include <cmath>
#include <fstream>

#include "tendril/core/data_table.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs::pneumatic {

namespace {

namespace fs = std::filesystem;

// The first line of the earlier format, which carried no checksum.
constexpr const char* kUncheckedTitle = "# tendril pneumatic-arm data set v1";

std::string chamber_column(const std::string& quantity, int m, int c) {
  return quantity + "_m" + std::to_string(m) + "_c" + std::to_string(c) + "_bar";
}

data::TableSchema make_schema(bool with_pressures) {
  using data::ColumnSpec;
  constexpr int kExact = ColumnSpec::kShortest;
  data::TableSchema schema{with_pressures ? "tendril.pneumatic_arm.data_set v2"
                                          : "tendril.pneumatic_arm.data_set_without_pressures v2",
                           {}};
  schema.columns.push_back(
      {"time_s", kExact, {}, "s since the recording began, strictly increasing"});
  const auto chambers = [&](const std::string& quantity, const std::string& description) {
    for (int m = 1; m <= 3; ++m) {
      for (int c = 1; c <= 3; ++c) {
        schema.columns.push_back(
            {chamber_column(quantity, m, c),
             kExact,
             {},
             description + " of module " + std::to_string(m) + ", chamber " + std::to_string(c)});
      }
    }
  };
  chambers("command",
           "bar, sent at time_s and held until the next row (0 to the command ceiling),");
  if (with_pressures) chambers("pressure", "bar, measured by the regulator at time_s,");
  for (int m = 1; m <= 3; ++m) {
    for (const char* axis : {"x", "y", "z"}) {
      schema.columns.push_back({"tip_m" + std::to_string(m) + "_" + axis + "_mm",
                                kExact,
                                {},
                                std::string("mm, tip of module ") + std::to_string(m) + ", " +
                                    axis + " in the robot frame (z negative downward), at time_s"});
    }
  }
  return schema;
}

std::string shortest(double value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

// The commands' upper bound: the metadata's command_ceiling_bar, else the regulators' 1.5 bar.
double command_ceiling(const std::vector<std::pair<std::string, std::string>>& metadata,
                       const std::string& where) {
  for (const auto& [key, value] : metadata) {
    if (key != "command_ceiling_bar") continue;
    double ceiling = 0.0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), ceiling);
    if (error != std::errc() || end != value.data() + value.size() || !std::isfinite(ceiling) ||
        ceiling <= 0.0) {
      throw Error("command_ceiling_bar: '" + value + "' is not a positive number", where);
    }
    return ceiling;
  }
  return kDefaultCommandCeilingBar;
}

// The metadata's `rows`, when it has one.
std::optional<long long> stated_rows(const std::vector<std::pair<std::string, std::string>>& meta,
                                     const std::string& where) {
  for (const auto& [key, value] : meta) {
    if (key != "rows") continue;
    long long rows = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), rows);
    if (error != std::errc() || end != value.data() + value.size() || rows < 0) {
      throw Error("rows: '" + value + "' is not a number of rows", where);
    }
    return rows;
  }
  return std::nullopt;
}

// The first row that breaks what a recording must satisfy, with why; -1 if none.
std::pair<Eigen::Index, std::string> first_bad_row(const PneumaticDataset& data, double ceiling) {
  for (Eigen::Index k = 0; k < data.time_s.size(); ++k) {
    if (k > 0 && !(data.time_s[k] > data.time_s[k - 1])) {
      return {k, "time_s must increase from row to row"};
    }
    for (int c = 0; c < 9; ++c) {
      const double command = data.commands_bar(k, c);
      if (command < 0.0 || command > ceiling) {
        return {k, "column " + chamber_column("command", c / 3 + 1, c % 3 + 1) + ": " +
                       shortest(command) + " bar lies outside [0, " + shortest(ceiling) +
                       "] (the regulators' command range)"};
      }
    }
  }
  return {-1, ""};
}

}  // namespace

std::optional<std::string> PneumaticDataset::meta(std::string_view key) const {
  for (const auto& [name, value] : metadata) {
    if (name == key) return value;
  }
  return std::nullopt;
}

const data::TableSchema& pneumatic_dataset_schema(bool with_pressures) {
  static const data::TableSchema with = make_schema(true), without = make_schema(false);
  return with_pressures ? with : without;
}

std::vector<std::string> pneumatic_dataset_columns(bool with_pressures) {
  std::vector<std::string> names;
  for (const data::ColumnSpec& column : pneumatic_dataset_schema(with_pressures).columns) {
    names.push_back(column.name);
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
  for (const auto& [key, value] : data.metadata) {
    require(!key.empty() && key.find_first_of(":\n\r") == std::string::npos && key.front() != ' ' &&
                key.back() != ' ',
            "metadata key '" + key + "' must be non-empty without ':', line breaks or edge spaces",
            where);
    require(value.find_first_of("\n\r") == std::string::npos,
            "metadata value of '" + key + "' must be one line", where);
  }
  const std::optional<long long> stated = stated_rows(data.metadata, where);
  require(!stated || *stated == rows,
          "its metadata says rows: " + std::to_string(stated.value_or(0)) + ", it holds " +
              std::to_string(rows),
          where);
  const auto [row, why] = first_bad_row(data, command_ceiling(data.metadata, where));
  if (row >= 0) throw Error(why, where + ", row " + std::to_string(row));
  require(!fs::exists(file), "the data set file exists; nothing was overwritten", where);

  data::Table table;
  table.metadata = data.metadata;
  const int width = data.has_pressures() ? 28 : 19;
  table.values.resize(rows, width);
  table.values.col(0) = data.time_s;
  table.values.middleCols(1, 9) = data.commands_bar;
  if (data.has_pressures()) table.values.middleCols(10, 9) = data.pressures_bar;
  table.values.rightCols(9) = data.tips_mm;
  if (!file.parent_path().empty()) fs::create_directories(file.parent_path());
  data::write_table(file, table, pneumatic_dataset_schema(data.has_pressures()));
}

PneumaticDataset read_pneumatic_dataset(const fs::path& file) {
  const std::string format = data::read_table_format(file);
  if (format.empty()) {
    std::ifstream in(file, std::ios::binary);
    std::string first;
    std::getline(in, first);
    if (!first.empty() && first.back() == '\r') first.pop_back();
    if (first == kUncheckedTitle) {
      throw Error(
          "a data set of the earlier format, which carries no checksum (damage to it "
          "cannot be told): collect it again — its '# command:' line says how",
          file.string() + ":1");
    }
  }
  const bool with_pressures = format != pneumatic_dataset_schema(false).format;
  const data::Table table = data::read_table(file, pneumatic_dataset_schema(with_pressures));
  const std::string where = file.string();
  if (table.rows() == 0) throw Error("the data set has no rows", where);

  PneumaticDataset data;
  data.metadata = table.metadata;
  data.time_s = table.values.col(0);
  data.commands_bar = table.values.middleCols(1, 9);
  if (with_pressures) data.pressures_bar = table.values.middleCols(10, 9);
  data.tips_mm = table.values.rightCols(9);

  const std::optional<long long> stated = stated_rows(data.metadata, where);
  if (stated && *stated != table.rows()) {
    throw Error("its header says rows: " + std::to_string(*stated) + ", it holds " +
                    std::to_string(table.rows()) +
                    " (cut short or joined with another file?); the last row is " +
                    table.where(table.rows() - 1),
                where);
  }
  const auto [row, why] = first_bad_row(data, command_ceiling(data.metadata, where));
  if (row >= 0) throw Error(why, table.where(row));
  return data;
}

}  // namespace tendril::envs::pneumatic
