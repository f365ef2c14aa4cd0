#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace tendril {

// The one error type of tendril: what was wrong, and where (a config key path, a file, a
// parameter name). Raised at the boundary — config, API entry, file load — so that code
// inside can trust its inputs.
class Error : public std::runtime_error {
 public:
  explicit Error(std::string what, std::string where = {});

  const std::string& what_wrong() const { return what_; }
  const std::string& where() const { return where_; }

 private:
  std::string what_;
  std::string where_;
};

// Throws Error(what, where) unless `condition` holds. Takes views so that a passing check
// builds no strings; on hot paths, give literals, or `if (!ok) throw Error(...)` when the
// message is composed.
inline void require(bool condition, std::string_view what, std::string_view where = {}) {
  if (!condition) throw Error(std::string(what), std::string(where));
}

}  // namespace tendril
