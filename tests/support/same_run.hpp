#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <map>
#include <string>
#include <utility>

#include "tendril/core/scalar_log.hpp"

namespace tendril::testing {

inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// (tag, step) → value over every event file of a run, wall-clock scalars aside; a scalar logged
// twice at one step (a resumed run that repeated its predecessor's rows) fails the test.
inline std::map<std::pair<std::string, int64_t>, float> event_scalars(
    const std::filesystem::path& run) {
  std::map<std::pair<std::string, int64_t>, float> scalars;
  for (const auto& entry : std::filesystem::directory_iterator(run)) {
    if (entry.path().filename().string().rfind("events.out.tfevents.", 0) != 0) continue;
    for (const EventScalar& s : read_event_scalars(entry.path())) {
      if (s.tag == "time/fps" || s.tag == "time/time_elapsed") continue;
      EXPECT_TRUE(scalars.emplace(std::make_pair(s.tag, s.step), s.value).second)
          << s.tag << " logged twice at step " << s.step;
    }
  }
  return scalars;
}

// A stopped and resumed run against the uninterrupted one: `files` byte for byte, and every
// logged scalar but the wall-clock ones.
inline void expect_same_run(const std::filesystem::path& run,
                            const std::filesystem::path& reference,
                            std::initializer_list<const char*> files) {
  for (const char* file : files) {
    ASSERT_TRUE(std::filesystem::exists(reference / file)) << file;
    EXPECT_EQ(file_text(run / file), file_text(reference / file)) << file;
  }
  EXPECT_EQ(event_scalars(run), event_scalars(reference));
}

}  // namespace tendril::testing
