#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#ifdef TENDRIL_WITH_DYNAMICS
#include "tendril/dynamics/env_model_loader.hpp"
#include "tendril/dynamics/policy_heads.hpp"
#endif
#include "support/error_message.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/safety/safety_evaluation.hpp"
#include "tendril/sweeps/sweep.hpp"

// Every training experiment and sweep file under configs/ reads: each key is known and valid,
// and the environment builds (rl::Experiment builds it once). A file that starts from the
// output of an earlier step (a learned model under runs/, a data set under data/) reads when
// that output exists and otherwise fails with an error naming it. Paths in the files are
// relative to the repository's root, as the README's commands run from there.
namespace tendril {
namespace {

const std::filesystem::path kRoot = std::filesystem::path(TENDRIL_CONFIG_DIR).parent_path();

std::vector<std::filesystem::path> yaml_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(TENDRIL_CONFIG_DIR)) {
    if (entry.is_regular_file() && entry.path().extension() == ".yaml") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The runs/ and data/ paths a file reads from (its `output:` excluded) that do not exist.
std::vector<std::string> missing_inputs(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> missing;
  const std::regex path_pattern(R"(\b(?:runs|data)/[A-Za-z0-9_./-]+)");
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    if (line.find("output:") != std::string::npos) continue;
    for (std::sregex_iterator it(line.begin(), line.end(), path_pattern), end; it != end; ++it) {
      if (!std::filesystem::exists(kRoot / it->str())) missing.push_back(it->str());
    }
  }
  return missing;
}

// Runs `read` and checks its outcome: success, or, for a file that lacks one of its inputs, an
// Error naming a missing input.
void expect_reads(const std::filesystem::path& file, const std::function<void()>& read) {
  const std::string message = testing::error_message(read);
  if (message == "no error") return;
  const std::vector<std::string> missing = missing_inputs(file);
  const bool names_missing = std::any_of(missing.begin(), missing.end(), [&](const auto& path) {
    return message.find(path) != std::string::npos;
  });
  EXPECT_TRUE(names_missing) << file << ": " << message;
}

class InRepositoryRoot : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_ = std::filesystem::current_path();
    std::filesystem::current_path(kRoot);
#ifdef TENDRIL_WITH_DYNAMICS
    dynamics::install_model_loader();
    dynamics::install_policy_heads();
#endif
  }
  void TearDown() override { std::filesystem::current_path(previous_); }

 private:
  std::filesystem::path previous_;
};

// Every file says what it is, and it is what the other tests below read it as.
TEST_F(InRepositoryRoot, EveryShippedFileNamesItsKind) {
  const std::vector<std::string> kinds = {"experiment",    "sweep",       "model_fit", "adaptation",
                                          "data_protocol", "calibration", "simulation"};
  for (const auto& file : yaml_files()) {
    SCOPED_TRACE(file.string());
    const Config config = Config::load_file(file);
    ASSERT_TRUE(config.has("kind"));
    const std::string kind = config.get<std::string>("kind");
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), kind), kinds.end()) << kind;
    EXPECT_EQ(kind == "experiment", config.has("algorithm") && !config.has("grid"));
    EXPECT_EQ(kind == "sweep", config.has("grid"));
  }
}

TEST_F(InRepositoryRoot, EveryShippedTrainingExperimentReads) {
  int experiments = 0;
  for (const auto& file : yaml_files()) {
    const Config config = Config::load_file(file);
    if (config.get<std::string>("kind") != "experiment") continue;
    ++experiments;
    SCOPED_TRACE(file.string());
    expect_reads(file, [&] { safety::task_experiment_of_config(config); });
  }
  EXPECT_GE(experiments, 60);  // the glob found configs/'s experiments
}

TEST_F(InRepositoryRoot, EveryRunOfEveryShippedSweepReads) {
  int sweeps = 0;
  for (const auto& file : yaml_files()) {
    if (Config::load_file(file).get<std::string>("kind") != "sweep") continue;
    ++sweeps;
    SCOPED_TRACE(file.string());
    // Loading checks every run's experiment, which may read an earlier step's output.
    const std::filesystem::path experiment =
        file.parent_path() / Config::load_file(file).get<std::string>("experiment");
    std::optional<sweeps::Sweep> loaded;
    expect_reads(experiment, [&] { loaded.emplace(sweeps::Sweep::load(file)); });
    if (!loaded) continue;
    const sweeps::Sweep& sweep = *loaded;
    const std::vector<sweeps::Sweep::Run> runs = sweep.runs();
    EXPECT_FALSE(runs.empty());
    for (const auto& run : runs) {
      SCOPED_TRACE(run.name);
      expect_reads(sweep.experiment_file,
                   [&] { safety::task_experiment_of_config(sweep.experiment(run)); });
    }
  }
  EXPECT_GE(sweeps, 40);
}

}  // namespace
}  // namespace tendril
