#pragma once

#include <stdexcept>
#include <string>

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

// Throws Error(what, where) unless `condition` holds.
inline void require(bool condition, const std::string& what, const std::string& where = {}) {
  if (!condition) throw Error(what, where);
}

}  // namespace tendril
