#include "tendril/core/error.hpp"

namespace tendril {

namespace {
std::string compose(const std::string& what, const std::string& where) {
  return where.empty() ? what : where + ": " + what;
}
}  // namespace

Error::Error(std::string what, std::string where)
    : std::runtime_error(compose(what, where)), what_(std::move(what)), where_(std::move(where)) {}

}  // namespace tendril
