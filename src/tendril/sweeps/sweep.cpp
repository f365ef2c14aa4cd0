#include "tendril/sweeps/sweep.hpp"

#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/rl/experiment.hpp"

namespace tendril::sweeps {

Sweep Sweep::load(const std::filesystem::path& file) {
  const Config config = Config::load_file(file);
  expect_kind(config, file_kind::kSweep);
  Sweep sweep;
  sweep.experiment_file = file.parent_path() / config.get<std::string>("experiment");
  for (const Config& axis : config.children("grid")) {
    const std::string key = axis.get<std::string>("key");
    const auto values = axis.get<std::vector<std::string>>("values");
    require(!values.empty(), "needs at least one value",
            axis.source() + ": " + axis.path() + ".values");
    sweep.grid.emplace_back(key, values);
  }
  require(!sweep.grid.empty(), "needs at least one axis", file.string() + ": grid");
  sweep.output = config.get<std::string>("output");
  config.reject_unknown();
  // Every run's experiment must load: a bad key or value fails before anything runs.
  for (const Run& run : sweep.runs()) rl::Experiment::from_config(sweep.experiment(run));
  return sweep;
}

std::vector<Sweep::Run> Sweep::runs() const {
  std::vector<Run> runs{Run{}};
  for (const auto& [key, values] : grid) {
    std::vector<Run> next;
    for (const Run& run : runs) {
      for (const std::string& value : values) {
        Run extended = run;
        const std::string short_key = key.substr(key.rfind('.') + 1);
        extended.name += (extended.name.empty() ? "" : "-") + short_key + "_" + value;
        extended.overrides.emplace_back(key, value);
        next.push_back(std::move(extended));
      }
    }
    runs = std::move(next);
  }
  return runs;
}

std::filesystem::path Sweep::directory(const Run& run) const {
  return std::filesystem::path(output) / run.name;
}

Config Sweep::experiment(const Run& run) const {
  Config config = Config::load_file(experiment_file);
  for (const auto& [key, value] : run.overrides) config.set(key, value);
  return config;
}

}  // namespace tendril::sweeps
