#pragma once

#include <functional>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::testing {

// The message of the tendril::Error that `action` raises, or "no error".
inline std::string error_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace tendril::testing
