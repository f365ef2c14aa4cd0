#include "tendril/hardware/safety_log.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"

namespace tendril::hardware {

SafetyLog::SafetyLog() : start_(std::chrono::steady_clock::now()) {}

SafetyLog::~SafetyLog() {
  if (file_ != nullptr) std::fclose(file_);
}

void SafetyLog::write_to(const std::filesystem::path& file) {
  std::FILE* opened = std::fopen(file.c_str(), "a");
  if (opened == nullptr) throw Error("cannot open the safety log for appending", file.string());
  if (file_ != nullptr) std::fclose(file_);
  file_ = opened;
  if (std::ftell(file_) == 0) std::fputs("time_s,action,cause\n", file_);
  std::fflush(file_);
}

void SafetyLog::record(const std::string& action, const std::string& cause) {
  const double time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  events_.push_back({time, action, cause});
  if (file_ != nullptr) {
    std::string quoted = cause;
    std::replace(quoted.begin(), quoted.end(), '"', '\'');
    std::fprintf(file_, "%.6f,%s,\"%s\"\n", time, action.c_str(), quoted.c_str());
    std::fflush(file_);
  }
}

int SafetyLog::count(const std::string& action) const {
  return static_cast<int>(std::count_if(events_.begin(), events_.end(),
                                        [&](const SafetyEvent& e) { return e.action == action; }));
}

}  // namespace tendril::hardware
