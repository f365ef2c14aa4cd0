#pragma once

// Stable-Baselines3's own training throughput, measured in the same run as tendril's: the
// anchors' script (anchors/bench/bench_sb3_pendulum.py, SB3 defaults on Gymnasium's
// Pendulum-v1, torch on one thread) over the vendored Stable-Baselines3 2.3.2 and Gymnasium
// 0.29.1, found beside the repository (../shared). Unset when they are not there or the run
// fails; the benchmark then says so instead of printing a ratio.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace tendril::bench {

inline std::optional<double> sb3_pendulum_steps_per_second(const std::string& algorithm,
                                                           long long steps) {
  const std::filesystem::path shared = TENDRIL_SHARED_DIR;
  const std::filesystem::path script = shared / "anchors/bench/bench_sb3_pendulum.py";
  const std::filesystem::path vendor = shared / "vendor";
  if (!std::filesystem::exists(script)) return std::nullopt;
  const std::string command = "OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 PYTHONPATH=" +
                              (vendor / "stable-baselines3-2.3.2").string() + ":" +
                              (vendor / "gymnasium-0.29.1").string() + " /usr/bin/python3 " +
                              script.string() + " --algo " + algorithm + " --steps " +
                              std::to_string(steps) + " --threads 1 --seed 0 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return std::nullopt;
  std::optional<double> rate;
  char line[1024];
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
    const std::string text(line);
    const std::size_t at = text.find("\"steps_per_s\": ");
    if (at != std::string::npos) rate = std::stod(text.substr(at + 15));
  }
  if (pclose(pipe) != 0) return std::nullopt;
  return rate;
}

// "59.6x": a ratio as the tables print it.
inline std::string ratio_text(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2fx", ratio);
  return text;
}

}  // namespace tendril::bench
