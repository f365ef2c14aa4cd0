#include "tendril/core/scalar_log.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril {

namespace {

// TFRecord's checksum: a rotated, offset CRC-32C.
uint32_t masked_crc(const void* data, std::size_t size) {
  const uint32_t crc = crc32c(data, size);
  return ((crc >> 15) | (crc << 17)) + 0xA282EAD8u;
}

// Minimal protobuf encoding (wire types 0 varint, 1 fixed64, 2 length-delimited, 5 fixed32).
void put_varint(std::string& out, uint64_t value) {
  while (value >= 0x80) {
    out.push_back(static_cast<char>((value & 0x7F) | 0x80));
    value >>= 7;
  }
  out.push_back(static_cast<char>(value));
}
template <typename T>
void put_fixed(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));  // little-endian host (x86-64, aarch64)
  out.append(bytes, sizeof(T));
}
void put_bytes(std::string& out, int field, const std::string& bytes) {
  put_varint(out, static_cast<uint64_t>(field) << 3 | 2);
  put_varint(out, bytes.size());
  out += bytes;
}

// tensorflow.Event { double wall_time = 1; int64 step = 2; string file_version = 3;
//                    Summary summary = 5; }, Summary { repeated Value value = 1; },
// Value { string tag = 1; float simple_value = 2; }.
std::string event(double wall_time, int64_t step, const std::string& file_version,
                  const std::map<std::string, double>& scalars) {
  std::string out;
  put_varint(out, 1 << 3 | 1);
  put_fixed(out, wall_time);
  put_varint(out, 2 << 3 | 0);
  put_varint(out, static_cast<uint64_t>(step));
  if (!file_version.empty()) put_bytes(out, 3, file_version);
  if (!scalars.empty()) {
    std::string summary;
    for (const auto& [tag, value] : scalars) {
      std::string entry;
      put_bytes(entry, 1, tag);
      put_varint(entry, 2 << 3 | 5);
      put_fixed(entry, static_cast<float>(value));
      put_bytes(summary, 1, entry);
    }
    put_bytes(out, 5, summary);
  }
  return out;
}

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string format(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

std::string csv_row(const std::vector<std::string>& row, std::size_t columns) {
  std::string text;
  for (std::size_t c = 0; c < columns; ++c) text += (c ? "," : "") + (c < row.size() ? row[c] : "");
  return text + '\n';
}

// One TFRecord: length, its masked CRC, the payload, the payload's masked CRC.
std::string record_of(const std::string& payload) {
  std::string record;
  const uint64_t length = payload.size();
  put_fixed(record, length);
  put_fixed(record, masked_crc(&length, sizeof length));
  record += payload;
  put_fixed(record, masked_crc(payload.data(), payload.size()));
  return record;
}

std::string read_whole(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) {
    throw Error("not a regular file: the log cannot be continued", file.string());
  }
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

ScalarLog::ScalarLog(const std::filesystem::path& directory, bool resume, int64_t resume_step)
    : csv_path_(directory / "progress.csv") {
  std::filesystem::create_directories(directory);
  bool dropped = false;
  if (resume && std::filesystem::exists(csv_path_)) {
    std::string text = read_whole(csv_path_);
    if (!text.empty() && text.back() != '\n') {  // a row cut short by a kill
      text.erase(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
      dropped = true;
    }
    std::istringstream in(text);
    std::string line;
    if (std::getline(in, line)) columns_ = split_csv_line(line);
    const auto step_column = std::find(columns_.begin(), columns_.end(), "time/total_timesteps");
    const std::size_t step_index = static_cast<std::size_t>(step_column - columns_.begin());
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      std::vector<std::string> row = split_csv_line(line);
      if (step_column != columns_.end() && step_index < row.size()) {
        double step = 0.0;
        const std::string& cell = row[step_index];
        const auto parsed = std::from_chars(cell.data(), cell.data() + cell.size(), step);
        if (parsed.ec == std::errc() && step > static_cast<double>(resume_step)) {
          dropped = true;
          continue;
        }
      }
      rows_.push_back(std::move(row));
    }
  }
  if (resume) {
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("events.out.tfevents.", 0) == 0 && !is_atomic_write_leftover(name) &&
          entry.is_regular_file()) {
        truncate_event_file(entry.path(), resume_step);
      }
    }
  }
  char host[256] = "localhost";
  gethostname(host, sizeof host - 1);
  const auto stamp = static_cast<long long>(now_seconds());
  event_path_ = directory / ("events.out.tfevents." + std::to_string(stamp) + "." + host);
  for (int suffix = 1; std::filesystem::exists(event_path_); ++suffix) {
    event_path_ = directory / ("events.out.tfevents." + std::to_string(stamp) + "." + host + "." +
                               std::to_string(suffix));
  }
  write_event(event(now_seconds(), 0, "brain.Event:2", {}));
  if (!resume || dropped || !std::filesystem::exists(csv_path_)) rewrite_csv();
}

void ScalarLog::write_event(const std::string& payload) {
  append_to_file(event_path_, record_of(payload), "the TensorBoard event file");
}

void ScalarLog::rewrite_csv() {
  std::string text;
  for (std::size_t c = 0; c < columns_.size(); ++c) text += (c ? "," : "") + columns_[c];
  if (!columns_.empty()) text += '\n';
  for (const auto& row : rows_) text += csv_row(row, columns_.size());
  write_file_atomically(csv_path_, text, "progress.csv");
}

void ScalarLog::dump(int64_t step) {
  if (pending_.empty()) return;
  bool widened = false;
  for (const auto& entry : pending_) {
    if (std::find(columns_.begin(), columns_.end(), entry.first) == columns_.end()) {
      columns_.push_back(entry.first);
      widened = true;
    }
  }
  std::vector<std::string> row(columns_.size());
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const auto found = pending_.find(columns_[c]);
    if (found != pending_.end()) row[c] = format(found->second);
  }
  rows_.push_back(row);
  if (widened || rows_.size() == 1) {
    rewrite_csv();
  } else {
    append_to_file(csv_path_, csv_row(row, row.size()), "progress.csv");
  }
  write_event(event(now_seconds(), step, "", pending_));
  pending_.clear();
}

void ScalarLog::write_events(int64_t step, const std::map<std::string, double>& scalars) {
  if (!scalars.empty()) write_event(event(now_seconds(), step, "", scalars));
}

namespace {

struct Reader {
  const std::string& bytes;
  std::size_t at;
  std::size_t end;
  const std::string& where;

  void need(std::size_t count) const {
    if (count > end - at) throw Error("truncated protobuf message", where);  // at ≤ end
  }
  uint64_t varint() {
    uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      need(1);
      const auto byte = static_cast<uint8_t>(bytes[at++]);
      value |= static_cast<uint64_t>(byte & 0x7F) << shift;
      if (!(byte & 0x80)) return value;
    }
    throw Error("malformed varint", where);
  }
  template <typename T>
  T fixed() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
  }
  Reader sub() {
    const uint64_t length = varint();
    need(length);
    Reader inner{bytes, at, at + length, where};
    at += length;
    return inner;
  }
  void skip(int wire_type) {
    if (wire_type == 0)
      varint();
    else if (wire_type == 1)
      fixed<uint64_t>();
    else if (wire_type == 2)
      sub();
    else if (wire_type == 5)
      fixed<uint32_t>();
    else
      throw Error("unknown protobuf wire type", where);
  }
};

}  // namespace

std::vector<EventScalar> read_event_scalars(const std::filesystem::path& file) {
  const std::string where = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot open event file", where);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<EventScalar> scalars;
  std::size_t at = 0;
  while (at < bytes.size()) {
    if (at + 12 > bytes.size()) throw Error("truncated record header", where);
    uint64_t length;
    uint32_t length_crc;
    std::memcpy(&length, bytes.data() + at, 8);
    std::memcpy(&length_crc, bytes.data() + at + 8, 4);
    if (length_crc != masked_crc(&length, 8)) throw Error("corrupt record length", where);
    const std::size_t available = bytes.size() - at - 12;  // payload and its CRC must fit here
    if (length > available || available - length < 4) throw Error("truncated record", where);
    uint32_t data_crc;
    std::memcpy(&data_crc, bytes.data() + at + 12 + length, 4);
    if (data_crc != masked_crc(bytes.data() + at + 12, length))
      throw Error("corrupt record", where);
    Reader event{bytes, at + 12, at + 12 + length, where};
    at += 12 + length + 4;
    int64_t step = 0;
    std::vector<std::pair<std::string, float>> values;
    while (event.at < event.end) {
      const uint64_t key = event.varint();
      const int field = static_cast<int>(key >> 3), wire = static_cast<int>(key & 7);
      if (field == 2 && wire == 0) {
        step = static_cast<int64_t>(event.varint());
      } else if (field == 5 && wire == 2) {
        Reader summary = event.sub();
        while (summary.at < summary.end) {
          const uint64_t summary_key = summary.varint();
          if (summary_key != (1 << 3 | 2)) {
            summary.skip(static_cast<int>(summary_key & 7));
            continue;
          }
          Reader value = summary.sub();
          std::string tag;
          float simple = 0.0f;
          while (value.at < value.end) {
            const uint64_t value_key = value.varint();
            if (value_key == (1 << 3 | 2)) {
              Reader text = value.sub();
              tag.assign(bytes, text.at, text.end - text.at);
            } else if (value_key == (2 << 3 | 5)) {
              simple = value.fixed<float>();
            } else {
              value.skip(static_cast<int>(value_key & 7));
            }
          }
          values.emplace_back(tag, simple);
        }
      } else {
        event.skip(wire);
      }
    }
    for (auto& [tag, value] : values) scalars.push_back({tag, step, value});
  }
  return scalars;
}

int truncate_event_file(const std::filesystem::path& file, int64_t last_step) {
  const std::string where = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot open event file", where);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string kept;
  int dropped = 0;
  std::size_t at = 0;
  while (at < bytes.size()) {
    uint64_t length = 0;
    uint32_t length_crc = 0, data_crc = 0;
    if (at + 12 > bytes.size()) break;
    std::memcpy(&length, bytes.data() + at, 8);
    std::memcpy(&length_crc, bytes.data() + at + 8, 4);
    if (length_crc != masked_crc(&length, 8) || length > bytes.size() - at - 16) break;
    std::memcpy(&data_crc, bytes.data() + at + 12 + length, 4);
    if (data_crc != masked_crc(bytes.data() + at + 12, length)) break;
    Reader event{bytes, at + 12, at + 12 + length, where};
    int64_t step = 0;
    try {
      while (event.at < event.end) {
        const uint64_t key = event.varint();
        if (key == (2 << 3 | 0)) {
          step = static_cast<int64_t>(event.varint());
        } else {
          event.skip(static_cast<int>(key & 7));
        }
      }
    } catch (const Error&) {
      break;
    }
    if (step <= last_step) {
      kept.append(bytes, at, 12 + length + 4);
    } else {
      ++dropped;
    }
    at += 12 + length + 4;
  }
  if (at < bytes.size()) ++dropped;  // a torn or corrupt tail
  if (dropped > 0) write_file_atomically(file, kept, "the TensorBoard event file");
  return dropped;
}

}  // namespace tendril
