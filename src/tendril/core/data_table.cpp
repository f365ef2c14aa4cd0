#include "tendril/core/data_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril::data {

namespace {

constexpr std::string_view kChecksumKey = "crc32c";

std::string location(const std::filesystem::path& file, std::size_t line) {
  return file.string() + ":" + std::to_string(line);
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// "-0", "-0.00": a negative zero, written without its sign.
void drop_negative_zero(char* field) {
  if (field[0] != '-') return;
  for (const char* p = field + 1; *p != '\0'; ++p) {
    if (*p != '0' && *p != '.') return;
  }
  for (char* p = field; *p != '\0'; ++p) p[0] = p[1];
}

std::string joined_names(const TableSchema& schema) {
  std::string names;
  for (const ColumnSpec& column : schema.columns) {
    names += (names.empty() ? "" : ",") + column.name;
  }
  return names;
}

double parse_field(std::string_view field, const ColumnSpec& column, const std::string& where) {
  if (column.is_text()) {
    for (std::size_t w = 0; w < column.words.size(); ++w) {
      if (field == column.words[w]) return static_cast<double>(w);
    }
    throw Error("column " + column.name + ": '" + std::string(field) + "' is not one of its words",
                where);
  }
  double value = 0.0;
  const char* end = field.data() + field.size();
  const auto [stop, error] = std::from_chars(field.data(), end, value);
  if (field.empty() || error != std::errc() || stop != end) {
    throw Error("column " + column.name + ": '" + std::string(field) + "' is not a number", where);
  }
  if (!std::isfinite(value)) {
    throw Error("column " + column.name + ": '" + std::string(field) + "' is not finite", where);
  }
  if (column.decimals == 0 && value != std::floor(value)) {  // kShortest takes any number
    throw Error("column " + column.name + ": '" + std::string(field) + "' is not an integer",
                where);
  }
  return value;
}

}  // namespace

int TableSchema::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].name == name) return static_cast<int>(c);
  }
  throw Error("no column '" + name + "'", format);
}

std::string Table::get(const std::string& key) const {
  for (const auto& [k, v] : metadata) {
    if (k == key) return v;
  }
  return "";
}

std::string Table::where(Eigen::Index row) const {
  if (row >= 0 && static_cast<std::size_t>(row) < source_lines.size()) {
    return location(source, source_lines[static_cast<std::size_t>(row)]);
  }
  return "row " + std::to_string(row);
}

void Table::set(const std::string& key, const std::string& value) {
  for (auto& [k, v] : metadata) {
    if (k == key) {
      v = value;
      return;
    }
  }
  metadata.emplace_back(key, value);
}

Table read_table(const std::filesystem::path& file, const TableSchema& schema) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot open data file", file.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (text.empty()) throw Error("empty data file", location(file, 1));
  reject_carriage_returns_only(text, file);
  // Before the checksum, which would call the cut damage.
  if (text.back() != '\n') {
    throw Error(
        "truncated: the last line has no line end (file cut short?)",
        location(file, 1 + static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'))));
  }
  verify_checksum(text, file);

  Table table;
  table.source = file;
  std::vector<double> values;
  const std::size_t width = schema.columns.size();
  const std::string expected_format = "# format: " + schema.format;
  const std::string header = joined_names(schema);
  bool header_seen = false;
  std::size_t line_number = 0, start = 0;
  while (start < text.size()) {
    ++line_number;
    const std::size_t end = text.find('\n', start);
    const std::string where = location(file, line_number);
    if (end == std::string::npos) {
      throw Error("truncated: the last line has no line end (file cut short?)", where);
    }
    std::string_view line(text.data() + start, end - start);
    start = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line_number == 1) {
      if (line != expected_format) {
        throw Error("expected '" + expected_format + "', got '" + std::string(line) + "'", where);
      }
      continue;
    }
    if (!header_seen) {
      if (!line.empty() && line.front() == '#') {
        const std::size_t colon = line.find(": ");
        if (line.size() < 3 || line[1] != ' ' || colon == std::string_view::npos || colon < 3) {
          throw Error("a header comment must read '# key: value'", where);
        }
        const std::string key(line.substr(2, colon - 2));
        if (key.rfind("column ", 0) != 0 && key != kChecksumKey) {
          table.metadata.emplace_back(key, std::string(line.substr(colon + 2)));
        }
        continue;
      }
      if (line != header) {
        throw Error("expected the column header '" + header + "', got '" + std::string(line) + "'",
                    where);
      }
      header_seen = true;
      continue;
    }
    const std::vector<std::string_view> fields = split(line);
    if (fields.size() != width) {
      throw Error(
          "expected " + std::to_string(width) + " fields, got " + std::to_string(fields.size()),
          where);
    }
    for (std::size_t c = 0; c < width; ++c) {
      values.push_back(parse_field(fields[c], schema.columns[c], where));
    }
    table.source_lines.push_back(line_number);
  }
  if (!header_seen) throw Error("no column header", location(file, line_number));
  const Eigen::Index rows = static_cast<Eigen::Index>(values.size() / width);
  table.values =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          values.data(), rows, static_cast<Eigen::Index>(width));
  return table;
}

std::string format_table(const Table& table, const TableSchema& schema) {
  const Eigen::Index width = static_cast<Eigen::Index>(schema.columns.size());
  if (table.values.cols() != width) {
    throw Error("table has " + std::to_string(table.values.cols()) + " columns, the schema " +
                    std::to_string(width),
                schema.format);
  }
  std::string text = "# format: " + schema.format + "\n";
  for (const ColumnSpec& column : schema.columns) {
    text += "# column " + column.name + ": " + column.description + "\n";
  }
  for (const auto& [key, value] : table.metadata) {
    if (key.empty() || key.find('\n') != std::string::npos ||
        value.find('\n') != std::string::npos || key.find(": ") != std::string::npos) {
      throw Error("metadata key '" + key + "' or its value cannot be written", schema.format);
    }
    text += "# " + key + ": " + value + "\n";
  }
  const std::string comments = std::move(text);
  text = joined_names(schema) + "\n";
  text.reserve(text.size() + static_cast<std::size_t>(table.rows()) * 12 * width);
  char field[64];
  for (Eigen::Index r = 0; r < table.rows(); ++r) {
    for (Eigen::Index c = 0; c < width; ++c) {
      const ColumnSpec& column = schema.columns[c];
      const double value = table.values(r, c);
      const std::string where = schema.format + ", row " + std::to_string(r);
      if (!std::isfinite(value)) throw Error("column " + column.name + " is not finite", where);
      if (column.is_text()) {
        if (value != std::floor(value) || value < 0 ||
            value >= static_cast<double>(column.words.size())) {
          throw Error("column " + column.name + " holds no word index", where);
        }
        text += column.words[static_cast<std::size_t>(value)];
      } else if (column.decimals == ColumnSpec::kShortest) {
        const auto end = std::to_chars(field, field + sizeof field, value).ptr;
        text.append(field, end);
      } else if (column.decimals == 0) {
        if (value != std::floor(value)) {
          throw Error("column " + column.name + " is not an integer", where);
        }
        std::snprintf(field, sizeof field, "%.0f", value);
        drop_negative_zero(field);
        text += field;
      } else {
        std::snprintf(field, sizeof field, "%.*f", column.decimals, value);
        drop_negative_zero(field);
        text += field;
      }
      text += c + 1 < width ? ',' : '\n';
    }
  }
  return checksummed(comments, text);
}

std::string checksummed(const std::string& comments, const std::string& body) {
  require(comments.empty() || comments.back() == '\n', "header comments must end a line",
          "checksummed");
  const std::string whole = comments + body;
  return comments + "# " + std::string(kChecksumKey) + ": " +
         checksum_text(crc32c(whole.data(), whole.size())) + "\n" + body;
}

std::string read_table_format(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot open data file", file.string());
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::string prefix = "# format: ";
  return line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : std::string();
}

void reject_carriage_returns_only(const std::string& text, const std::filesystem::path& file) {
  if (text.find('\n') == std::string::npos && text.find('\r') != std::string::npos) {
    throw Error(
        "its lines end in a carriage return alone (classic Mac line ends): convert them "
        "to '\\n' line ends",
        location(file, 1));
  }
}

void verify_checksum(const std::string& text, const std::filesystem::path& file) {
  // Only header lines start with '#', so the first line of this form is the checksum line.
  const std::string prefix = "# " + std::string(kChecksumKey) + ": ";
  std::size_t begin = 0;
  if (text.rfind(prefix, 0) != 0) {
    begin = text.find("\n" + prefix);
    if (begin == std::string::npos) return;  // written outside tendril: nothing to verify
    ++begin;
  }
  const std::size_t end = text.find('\n', begin);
  if (end == std::string::npos) throw Error("truncated in its checksum line", file.string());
  const std::size_t value = begin + prefix.size();
  std::string stored = text.substr(value, end - value);
  const std::string where = location(
      file, 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + begin, '\n')));
  if (!stored.empty() && stored.back() == '\r') {
    // The file was written with '\n' line ends; '\r\n' ones are a change (an editor, a
    // transfer in text mode), which the checksum cannot tell from damage.
    throw Error(
        "its line ends were changed to CRLF ('\\r\\n') after it was written, so its "
        "checksum no longer holds: convert them back to '\\n', or delete the checksum "
        "line to read it as it is",
        where);
  }
  const std::string rest = text.substr(0, begin) + text.substr(end + 1);
  const std::string computed = checksum_text(crc32c(rest.data(), rest.size()));
  if (stored != computed) {
    throw Error("corrupt: its CRC-32C is " + computed + ", its checksum line says '" + stored +
                    "' (changed or damaged after it was written; delete that line to read a "
                    "deliberately edited file)",
                where);
  }
}

void write_table(const std::filesystem::path& file, const Table& table, const TableSchema& schema) {
  write_new_file_atomically(file, format_table(table, schema), "data");
}

}  // namespace tendril::data
