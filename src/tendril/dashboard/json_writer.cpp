#include "tendril/dashboard/json_writer.hpp"

#include <cmath>
#include <cstdio>

namespace tendril::dashboard {

std::string json_string(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out.push_back('"');
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
          out += escaped;
        } else {
          out.push_back(c);
        }
    }
  }
  out.push_back('"');
  return out;
}

void JsonWriter::separate() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_.empty()) {
    if (!first_.back()) text_.push_back(',');
    first_.back() = false;
  }
}

JsonWriter& JsonWriter::begin_object() {
  separate();
  text_.push_back('{');
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::end_object() {
  text_.push_back('}');
  first_.pop_back();
  return *this;
}

JsonWriter& JsonWriter::begin_array() {
  separate();
  text_.push_back('[');
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::end_array() {
  text_.push_back(']');
  first_.pop_back();
  return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  separate();
  text_ += json_string(name);
  text_.push_back(':');
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
  separate();
  text_ += json_string(text);
  return *this;
}

void JsonWriter::number(double value, int digits) {
  if (!std::isfinite(value)) {
    text_ += "null";
    return;
  }
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  text_ += buffer;
}

JsonWriter& JsonWriter::value(double number_value) {
  separate();
  number(number_value, 17);
  return *this;
}

JsonWriter& JsonWriter::value(double number_value, int digits) {
  separate();
  number(number_value, digits);
  return *this;
}

JsonWriter& JsonWriter::value(int64_t number_value) {
  separate();
  text_ += std::to_string(number_value);
  return *this;
}

JsonWriter& JsonWriter::value(bool flag) {
  separate();
  text_ += flag ? "true" : "false";
  return *this;
}

JsonWriter& JsonWriter::null() {
  separate();
  text_ += "null";
  return *this;
}

JsonWriter& JsonWriter::numbers(const float* data, std::size_t count, int digits) {
  begin_array();
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) text_.push_back(',');
    number(static_cast<double>(data[i]), digits);
  }
  first_.back() = count == 0;
  return end_array();
}

JsonWriter& JsonWriter::numbers(const std::vector<double>& values, int digits) {
  begin_array();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text_.push_back(',');
    number(values[i], digits);
  }
  first_.back() = values.empty();
  return end_array();
}

}  // namespace tendril::dashboard
