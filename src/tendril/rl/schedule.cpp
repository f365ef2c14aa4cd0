#include "tendril/rl/schedule.hpp"

#include "tendril/core/error.hpp"

namespace tendril::rl {

Schedule read_schedule(const Config& algo, const std::string& key, const Schedule& fallback) {
  Schedule schedule = fallback;
  schedule.initial = algo.get_or<double>(key, fallback.initial);
  const std::string schedule_key = key + "_schedule";
  const std::string kind =
      algo.get_or<std::string>(schedule_key, fallback.linear ? "linear" : "constant");
  if (kind != "constant" && kind != "linear") {
    throw Error("expected constant or linear, got '" + kind + "'", algo.where(schedule_key));
  }
  schedule.linear = kind == "linear";
  return schedule;
}

}  // namespace tendril::rl
