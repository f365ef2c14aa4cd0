#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tendril::dashboard {

// The rows of a numeric CSV file (progress.csv, eval.csv) from a byte offset on, for charts that
// follow a run while it trains: a poll asks from the `next_offset` of the previous one. Only
// complete lines are returned: an unterminated last line (being written) waits for the next poll.
// A file shorter than the offset (rewritten, as progress.csv is when a column is added) is read
// from its start again, and so should a client whose columns no longer match. A slice reads a
// bounded number of lines and lists a bounded number of problems, so that its answer stays a
// small multiple of what it reads (a client asks again from next_offset while `more`).
struct CsvSlice {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;  // empty or non-numeric cells as NaN
  int64_t first_line = 0;                 // 1-based line number of rows[0]
  uint64_t next_offset = 0;
  uint64_t size = 0;
  bool restarted = false;     // the offset lay past the end: rows are from the start
  bool partial_line = false;  // the file ends inside a line
  bool more = false;          // complete lines are left after next_offset (the line limit)
  // Malformed lines, each as "line N: what is wrong", the first max_problems of them; a row with
  // the wrong number of cells is left out, a non-numeric cell becomes NaN.
  std::vector<std::string> problems;
  int64_t problem_count = 0;  // every problem of the lines read, listed or not
};

struct CsvSliceLimits {
  std::size_t max_lines = 50000;     // lines read (rows, malformed and blank ones) per slice
  std::size_t max_problems = 100;    // problems listed per slice
  uint64_t max_bytes = 64ull << 20;  // a larger file is refused
};

// Raises Error when the file cannot be read or exceeds `limits.max_bytes`.
CsvSlice read_csv_slice(const std::filesystem::path& file, uint64_t offset,
                        const CsvSliceLimits& limits = {});

}  // namespace tendril::dashboard
