#pragma once

#include <sstream>
#include <string>

namespace tendril::log {

enum class Level { kDebug = 0, kInfo = 1, kWarning = 2, kError = 3, kOff = 4 };

// Messages below this level are dropped. Default: kInfo, or TENDRIL_LOG_LEVEL
// (debug|info|warning|error|off) from the environment.
void set_level(Level level);
Level level();

// Writes one line "[level] message" to standard error; safe to call from several threads.
void write(Level level, const std::string& message);

template <typename... Parts>
void emit(Level at, const Parts&... parts) {
  if (at < level()) return;
  std::ostringstream line;
  (line << ... << parts);
  write(at, line.str());
}

template <typename... Parts>
void debug(const Parts&... parts) { emit(Level::kDebug, parts...); }
template <typename... Parts>
void info(const Parts&... parts) { emit(Level::kInfo, parts...); }
template <typename... Parts>
void warning(const Parts&... parts) { emit(Level::kWarning, parts...); }
template <typename... Parts>
void error(const Parts&... parts) { emit(Level::kError, parts...); }

}  // namespace tendril::log
