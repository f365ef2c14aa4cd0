#include "tendril/rl/schedule.hpp"

#include <cmath>

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
  const std::string final_key = key + "_final";
  if (schedule.linear) {
    schedule.final = algo.get_or<double>(final_key, fallback.final);
    if (!std::isfinite(schedule.final) || schedule.final < 0.0) {
      throw Error("must be finite and >= 0", algo.where(final_key));
    }
  } else if (algo.has(final_key) && algo.get<double>(final_key) != 0.0) {
    // A constant schedule has no end value (0, the default, is accepted as written).
    throw Error("needs " + schedule_key + ": linear", algo.where(final_key));
  }
  return schedule;
}

}  // namespace tendril::rl
