#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

// The one format of tendril's data files: every robot's data set (the SMA limb's in data/, the
// pneumatic arm's in envs/pneumatic/) and the prepared sets the learned models fit. It sits in
// core, below every layer that reads or writes such a file.
namespace tendril::data {

// One column of a data file: its name, how it is written, and one line of documentation that
// the file's header carries.
struct ColumnSpec {
  // `decimals` of a column written as the shortest text that reads back as exactly its value
  // (std::to_chars): measurements kept at their own resolution.
  static constexpr int kShortest = -1;

  std::string name;
  int decimals = 0;                // digits after the point; 0: an integer column; or kShortest
  std::vector<std::string> words;  // non-empty: a text column holding one of these words
  std::string description;         // units and meaning

  bool is_text() const { return !words.empty(); }
};

// The layout of one kind of data file: a format tag with its version and the columns, in order.
struct TableSchema {
  std::string format;  // e.g. "tendril.sma_limb.data_set v1"
  std::vector<ColumnSpec> columns;

  int column(const std::string& name) const;  // index; Error if absent
};

// A data file in memory: free-form metadata and one row of values per record, in the schema's
// column order (text columns hold the index of their word).
struct Table {
  std::vector<std::pair<std::string, std::string>> metadata;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> values;
  // For a table read from a file, the file and the line each row came from (for error messages).
  std::filesystem::path source;
  std::vector<std::size_t> source_lines;

  Eigen::Index rows() const { return values.rows(); }
  // "<file>:<line>" of row r when read from a file, else "row r".
  std::string where(Eigen::Index row) const;
  // The value of a metadata key, or "" if absent; set replaces or appends.
  std::string get(const std::string& key) const;
  void set(const std::string& key, const std::string& value);
};

// The file format (CSV with a commented header, so that `pandas.read_csv(path, comment="#")` or
// `numpy.genfromtxt(path, delimiter=",", names=True, comments="#", dtype=None)` reads it):
//   # format: <schema.format>
//   # column <name>: <description>          (one per column, in order)
//   # <key>: <value>                        (the metadata, in order)
//   # crc32c: <8 hex digits>                (CRC-32C of every byte of the file but this line)
//   <name>,<name>,...                       (the column header)
//   <value>,<value>,...                     (one line per row, every line ending in '\n')
// Numbers are written with the column's decimals (integers without a point; kShortest columns
// as the shortest exact text), text columns as their word.
//
// read_table is strict: the format line, the header and every field must be exactly as the
// schema says, numbers finite and wholly parsed, integer columns integral, words known, and the
// file must end with a line end (a file cut short is reported, not half-read). Every error is a
// tendril::Error naming the file and line. A file carrying a checksum line must match it (a
// changed or damaged data set is refused before use); a file without one (data written by
// other software) is read as it is. write_table never replaces an existing file and
// writes atomically (core/atomic_file.hpp); a value that the schema cannot represent (NaN, a
// non-integral integer, an unknown word) is an Error naming the row and column.
Table read_table(const std::filesystem::path& file, const TableSchema& schema);
// The format a data file names on its first line ("# format: <format>"), or "" when its first
// line is no format line; for readers that take one of several schemas. Error when the file
// cannot be opened.
std::string read_table_format(const std::filesystem::path& file);
void write_table(const std::filesystem::path& file, const Table& table, const TableSchema& schema);
// The text write_table writes.
std::string format_table(const Table& table, const TableSchema& schema);
// A data file's text: `comments` ('#' lines), the checksum line over both, then `body`.
std::string checksummed(const std::string& comments, const std::string& body);
// Raises Error naming `file` and the line if `text` (a whole data file) carries a checksum line
// that does not match it (saying so when only its line ends were changed to CRLF); for readers of
// these files outside read_table.
void verify_checksum(const std::string& text, const std::filesystem::path& file);
// Raises Error naming `file` if `text` ends its lines in a carriage return alone (it would read
// as one line).
void reject_carriage_returns_only(const std::string& text, const std::filesystem::path& file);

}  // namespace tendril::data
