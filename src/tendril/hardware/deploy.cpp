#include "tendril/hardware/deploy.hpp"

#include <cstdio>
#include <memory>

#include "tendril/core/error.hpp"

namespace tendril::hardware {

namespace {

struct CsvFile {
  std::FILE* file = nullptr;
  bool header = false;
  ~CsvFile() {
    if (file != nullptr) std::fclose(file);
  }
};

}  // namespace

DeployResult deploy(Env& env, const std::function<Action(const Observation&)>& actor,
                    const DeployOptions& options, const std::function<void()>& on_fault) {
  require(options.episodes >= 1 && options.max_steps >= 0,
          "episodes must be >= 1 and max_steps >= 0", "deploy");
  CsvFile csv;
  if (!options.csv.empty()) {
    csv.file = std::fopen(options.csv.c_str(), "w");
    if (csv.file == nullptr) throw Error("cannot write", options.csv.string());
  }
  DeployResult result;
  try {
    for (int episode = 0; episode < options.episodes; ++episode) {
      Observation observation = env.reset(options.seed + static_cast<uint64_t>(episode));
      double total = 0.0;
      for (int step = 0; options.max_steps == 0 || step < options.max_steps; ++step) {
        const Action action = actor(observation);
        const Step s = env.step(action);
        total += s.reward;
        ++result.steps;
        if (csv.file != nullptr) {
          if (!csv.header) {
            std::fputs("episode,step,reward,terminated,truncated", csv.file);
            for (Eigen::Index i = 0; i < action.size(); ++i)
              std::fprintf(csv.file, ",action_%ld", static_cast<long>(i));
            for (Eigen::Index i = 0; i < s.observation.size(); ++i) {
              std::fprintf(csv.file, ",observation_%ld", static_cast<long>(i));
            }
            for (const auto& entry : s.info.entries())
              std::fprintf(csv.file, ",%s", entry.first.c_str());
            std::fputc('\n', csv.file);
            csv.header = true;
          }
          std::fprintf(csv.file, "%d,%d,%.17g,%d,%d", episode, step, s.reward, s.terminated,
                       s.truncated);
          for (Eigen::Index i = 0; i < action.size(); ++i)
            std::fprintf(csv.file, ",%.9g", action[i]);
          for (Eigen::Index i = 0; i < s.observation.size(); ++i) {
            std::fprintf(csv.file, ",%.9g", s.observation[i]);
          }
          for (const auto& entry : s.info.entries()) std::fprintf(csv.file, ",%.17g", entry.second);
          std::fputc('\n', csv.file);
          std::fflush(csv.file);
        }
        observation = s.observation;
        if (options.stop != nullptr && options.stop->load()) {
          result.stopped = true;
          break;
        }
        if (s.terminated || s.truncated) break;
      }
      result.returns.push_back(total);
      ++result.episodes;
      if (result.stopped) break;
    }
  } catch (const Error& error) {
    if (on_fault) on_fault();
    result.fault = error.what();
  }
  return result;
}

}  // namespace tendril::hardware
