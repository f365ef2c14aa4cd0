#include "tendril/dashboard/csv_slice.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string_view>

#include "tendril/core/error.hpp"

namespace tendril::dashboard {

namespace {

constexpr std::size_t kMaxColumns = 10000;

std::vector<std::string_view> split_cells(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(
        line.substr(start, comma == std::string_view::npos ? line.npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '"')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '"' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return text;
}

// The number in `cell`; NaN for an empty cell; false for text that is not a number.
bool parse_cell(std::string_view cell, double& value) {
  cell = trim(cell);
  if (cell.empty()) {
    value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (cell.front() == '+') cell.remove_prefix(1);
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  return error == std::errc() && end == cell.data() + cell.size();
}

}  // namespace

CsvSlice read_csv_slice(const std::filesystem::path& file, uint64_t offset,
                        const CsvSliceLimits& limits) {
  std::error_code error;
  const uint64_t size = std::filesystem::file_size(file, error);
  require(!error, "cannot read the file", file.string());
  require(size <= limits.max_bytes, "too large to serve (" + std::to_string(size) + " bytes)",
          file.string());
  std::ifstream in(file, std::ios::binary);
  require(in.good(), "cannot open the file", file.string());
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

  CsvSlice slice;
  slice.size = text.size();
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos) {  // not even a complete header yet
    slice.partial_line = !text.empty();
    return slice;
  }
  const std::vector<std::string_view> header =
      split_cells(std::string_view(text).substr(0, header_end));
  require(header.size() <= kMaxColumns,
          "a header of " + std::to_string(header.size()) + " columns (at most " +
              std::to_string(kMaxColumns) + " are read)",
          file.string());
  for (std::string_view column : header) slice.columns.emplace_back(trim(column));
  std::size_t position = header_end + 1;
  if (offset > text.size()) slice.restarted = true;
  if (offset > position && offset <= text.size()) position = static_cast<std::size_t>(offset);
  // A position inside a line (not after a newline) belongs to a file that was rewritten.
  if (position > header_end + 1 && text[position - 1] != '\n') {
    slice.restarted = true;
    position = header_end + 1;
  }
  int64_t line_number =
      1 + static_cast<int64_t>(std::count(text.begin(), text.begin() + position, '\n'));
  slice.first_line = line_number;
  bool first_row = true;
  auto problem = [&](std::string what) {
    if (slice.problems.size() < limits.max_problems) slice.problems.push_back(std::move(what));
    ++slice.problem_count;
  };
  std::size_t lines = 0;
  while (position < text.size()) {
    const std::size_t end = text.find('\n', position);
    if (end != std::string::npos && lines++ == limits.max_lines) {
      slice.more = true;
      break;
    }
    if (end == std::string::npos) {
      slice.partial_line = true;
      break;
    }
    const std::string_view line = std::string_view(text).substr(position, end - position);
    position = end + 1;
    if (trim(line).empty()) {
      ++line_number;
      continue;
    }
    const std::vector<std::string_view> cells = split_cells(line);
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (cells.size() != slice.columns.size()) {
      problem(where + std::to_string(cells.size()) + " cells, the header has " +
              std::to_string(slice.columns.size()));
    } else {
      std::vector<double> row(cells.size());
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!parse_cell(cells[c], row[c])) {
          row[c] = std::numeric_limits<double>::quiet_NaN();
          problem(where + "'" + std::string(trim(cells[c]).substr(0, 40)) + "' in column " +
                  slice.columns[c] + " is not a number");
        }
      }
      if (first_row) slice.first_line = line_number;
      first_row = false;
      slice.rows.push_back(std::move(row));
    }
    ++line_number;
  }
  slice.next_offset = position;
  return slice;
}

}  // namespace tendril::dashboard
