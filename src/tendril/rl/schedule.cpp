#include "tendril/rl/schedule.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

Schedule read_schedule(const Config& algo, const std::string& key, const Schedule& fallback) {
  Schedule schedule = fallback;
  schedule.initial = algo.get_or<double>(key, fallback.initial);
  const std::string schedule_key = key + "_schedule";
  if (algo.has(schedule_key)) {
    const std::string kind = algo.get<std::string>(schedule_key);
    if (kind != "constant" && kind != "linear") {
      const std::string path =
          algo.path().empty() ? schedule_key : algo.path() + "." + schedule_key;
      throw Error("expected constant or linear, got '" + kind + "'", algo.source() + ": " + path);
    }
    schedule.linear = kind == "linear";
  }
  return schedule;
}

}  // namespace tendril::rl
