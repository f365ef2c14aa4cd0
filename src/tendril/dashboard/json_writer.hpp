#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tendril::dashboard {

// Builds a JSON text in one pass: objects, arrays, strings (escaped), numbers (non-finite ones
// become null, which JSON lacks a spelling for), booleans. Commas are placed by the writer;
// keys are given before each member of an object.
class JsonWriter {
 public:
  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(std::string_view name);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(const std::string& text) { return value(std::string_view(text)); }
  JsonWriter& value(double number);  // exactly (17 significant digits)
  JsonWriter& value(double number, int digits);
  JsonWriter& value(int64_t number);
  JsonWriter& value(int number) { return value(static_cast<int64_t>(number)); }
  JsonWriter& value(uint64_t number) { return value(static_cast<int64_t>(number)); }
  JsonWriter& value(bool flag);
  JsonWriter& null();
  // Numbers with `digits` significant digits (float32 data needs no more than 9).
  JsonWriter& numbers(const float* data, std::size_t count, int digits = 7);
  JsonWriter& numbers(const std::vector<double>& values, int digits = 17);

  const std::string& str() const { return text_; }

 private:
  void separate();
  void number(double value, int digits);

  std::string text_;
  std::vector<bool> first_;  // per open container: no member written yet
  bool after_key_ = false;
};

// `text` as a JSON string literal, quotes included.
std::string json_string(std::string_view text);

}  // namespace tendril::dashboard
