// libFuzzer target: an experiment's YAML text and `--set key=value` overrides, through the
// typed, key-marking reads of tendril::Config. Input: the YAML document, then optionally a line
// "#overrides" followed by one dotted.key=value per line. Any exception but tendril::Error is a
// failure (bad input must raise an Error naming what is wrong), as is any sanitizer report.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/core/error.hpp"

namespace {

using tendril::Config;
using tendril::Error;

template <typename T>
void try_get(const Config& config, const std::string& key) {
  try {
    (void)config.get<T>(key);
  } catch (const Error&) {
  }
}

// Reads every key below `config` as every type a caller might ask for.
void read_everything(const Config& config, int depth) {
  if (depth > 8) return;
  for (const std::string& key : config.keys()) {
    try_get<double>(config, key);
    try_get<int64_t>(config, key);
    try_get<int>(config, key);
    try_get<uint64_t>(config, key);
    try_get<bool>(config, key);
    try_get<std::string>(config, key);
    try_get<std::vector<double>>(config, key);
    try_get<std::vector<int64_t>>(config, key);
    try_get<std::vector<std::string>>(config, key);
    try {
      read_everything(config.child(key), depth + 1);
    } catch (const Error&) {
    }
    try {
      for (const Config& item : config.children(key)) read_everything(item, depth + 1);
    } catch (const Error&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string_view marker = "\n#overrides\n";
  const size_t split = input.find(marker);
  const std::string_view yaml = input.substr(0, split);
  try {
    Config config = Config::parse(yaml, "fuzz.yaml");
    if (split != std::string_view::npos) {
      std::string_view rest = input.substr(split + marker.size());
      while (!rest.empty()) {
        const size_t end = rest.find('\n');
        const std::string_view line = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
        const size_t equals = line.find('=');
        if (equals == std::string_view::npos) continue;
        try {
          config.set(line.substr(0, equals), line.substr(equals + 1));
        } catch (const Error&) {
        }
      }
    }
    try {
      config.reject_unknown();
    } catch (const Error&) {
    }
    read_everything(config, 0);
    config.reject_unknown();  // everything was read
    // What dump() writes parses back.
    const Config again = Config::parse(config.dump(), "dump.yaml");
    read_everything(again, 0);
  } catch (const Error&) {
  }
  return 0;
}
