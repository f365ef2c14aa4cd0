#include "tendril/core/log.hpp"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>

namespace tendril::log {

namespace {

Level level_from_environment() {
  const char* text = std::getenv("TENDRIL_LOG_LEVEL");
  if (text == nullptr) return Level::kInfo;
  if (std::strcmp(text, "debug") == 0) return Level::kDebug;
  if (std::strcmp(text, "warning") == 0) return Level::kWarning;
  if (std::strcmp(text, "error") == 0) return Level::kError;
  if (std::strcmp(text, "off") == 0) return Level::kOff;
  return Level::kInfo;
}

std::atomic<Level>& current_level() {
  static std::atomic<Level> value{level_from_environment()};
  return value;
}

const char* label(Level level) {
  switch (level) {
    case Level::kDebug: return "debug";
    case Level::kInfo: return "info";
    case Level::kWarning: return "warning";
    case Level::kError: return "error";
    case Level::kOff: return "off";
  }
  return "?";
}

}  // namespace

void set_level(Level level) { current_level().store(level); }
Level level() { return current_level().load(); }

void write(Level level, const std::string& message) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  std::cerr << '[' << label(level) << "] " << message << '\n';
}

}  // namespace tendril::log
