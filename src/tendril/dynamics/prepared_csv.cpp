#include "tendril/dynamics/prepared_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/data_table.hpp"
#include "tendril/core/error.hpp"

namespace tendril::dynamics {

namespace {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) {
    text.remove_suffix(1);
  }
  return text;
}

std::string where(const std::filesystem::path& file, int64_t line) {
  return file.string() + ":" + std::to_string(line);
}

double parse_number(std::string_view field, const std::string& column,
                    const std::filesystem::path& file, int64_t line) {
  const std::string_view text = trimmed(field);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    throw Error("column '" + column + "': '" + std::string(text) + "' is not a finite number",
                where(file, line));
  }
  return value;
}

void append_number(std::string& out, double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  out.append(text, end);
}

}  // namespace

SequenceData read_prepared_csv(const std::filesystem::path& file, const CsvColumns& columns) {
  std::ifstream stream(file, std::ios::binary);
  require(stream.good() && std::filesystem::is_regular_file(file), "cannot open the data file",
          file.string());
  const std::string text((std::istreambuf_iterator<char>(stream)),
                         std::istreambuf_iterator<char>());
  data::reject_carriage_returns_only(text, file);
  data::verify_checksum(text, file);
  std::istringstream in(text);
  // Data files (core/data_table.hpp) open with '#' lines: format, columns, metadata,
  // checksum.
  std::string line;
  int64_t line_number = 0;
  do {
    require(static_cast<bool>(std::getline(in, line)), "empty data file (no header)",
            file.string());
    ++line_number;
  } while (!line.empty() && line.front() == '#');
  const int64_t header_line = line_number;
  const std::vector<std::string_view> header_fields = split_fields(line);
  std::vector<std::string> header;
  for (std::string_view name : header_fields) header.emplace_back(trimmed(name));
  auto column_index = [&](const std::string& name) {
    const auto found = std::find(header.begin(), header.end(), name);
    if (found == header.end()) {
      throw Error("no column '" + name + "' in the header", where(file, header_line));
    }
    return static_cast<std::size_t>(found - header.begin());
  };
  const std::size_t time_column = column_index("time_s");
  const std::size_t split_column = column_index("split");
  std::vector<std::size_t> state_columns, input_columns;
  for (const std::string& name : columns.states) state_columns.push_back(column_index(name));
  for (const std::string& name : columns.inputs) input_columns.push_back(column_index(name));

  std::vector<double> time, states, inputs;
  std::vector<Split> split;
  std::vector<int64_t> lines;
  while (std::getline(in, line)) {
    ++line_number;
    if (trimmed(line).empty()) continue;
    lines.push_back(line_number);
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.size() != header.size()) {
      throw Error("has " + std::to_string(fields.size()) + " fields, the header " +
                      std::to_string(header.size()) + " (truncated or malformed row)",
                  where(file, line_number));
    }
    time.push_back(parse_number(fields[time_column], "time_s", file, line_number));
    for (std::size_t i = 0; i < state_columns.size(); ++i) {
      states.push_back(
          parse_number(fields[state_columns[i]], columns.states[i], file, line_number));
    }
    for (std::size_t i = 0; i < input_columns.size(); ++i) {
      inputs.push_back(
          parse_number(fields[input_columns[i]], columns.inputs[i], file, line_number));
    }
    const std::string_view mark = trimmed(fields[split_column]);
    if (mark == "train") {
      split.push_back(Split::kTrain);
    } else if (mark == "test") {
      split.push_back(Split::kTest);
    } else {
      throw Error("column 'split': '" + std::string(mark) + "' is neither train nor test",
                  where(file, line_number));
    }
  }
  require(!time.empty(), "has a header but no rows", file.string());

  SequenceData data;
  data.source = file.string();
  data.state_names = columns.states;
  data.input_names = columns.inputs;
  const auto n = static_cast<Eigen::Index>(time.size());
  data.time = Eigen::Map<const Eigen::VectorXd>(time.data(), n);
  data.states = Eigen::Map<const RowMatrixXd>(states.data(), n,
                                              static_cast<Eigen::Index>(state_columns.size()));
  data.inputs = Eigen::Map<const RowMatrixXd>(inputs.data(), n,
                                              static_cast<Eigen::Index>(input_columns.size()));
  data.split = std::move(split);
  data.lines = std::move(lines);
  data.validate();
  return data;
}

void write_prepared_csv(const SequenceData& data, const std::filesystem::path& file) {
  data.validate();
  require(!std::filesystem::exists(file), "exists; nothing is overwritten", file.string());
  std::string out = "time_s";
  for (const std::string& name : data.state_names) out += "," + name;
  for (const std::string& name : data.input_names) out += "," + name;
  out += ",split\n";
  for (int64_t t = 0; t < data.rows(); ++t) {
    append_number(out, data.time(t));
    for (Eigen::Index c = 0; c < data.states.cols(); ++c) {
      out += ',';
      append_number(out, data.states(t, c));
    }
    for (Eigen::Index c = 0; c < data.inputs.cols(); ++c) {
      out += ',';
      append_number(out, data.inputs(t, c));
    }
    out += data.split[t] == Split::kTrain ? ",train\n" : ",test\n";
  }
  write_file_atomically(file, data::checksummed("", out), "data set");
}

}  // namespace tendril::dynamics
