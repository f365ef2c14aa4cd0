#include "tendril/dynamics/fit_run.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <iterator>
#include <sstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "synthetic_limb.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/scalar_log.hpp"
#include "tendril/dynamics/model.hpp"
#include "tendril/dynamics/model_file.hpp"

namespace tendril::dynamics {
namespace {

using testing::error_message;

class FitRun : public testing::ScratchDirectoryTest {
 protected:
  FitRun() : ScratchDirectoryTest("fit_run") {}

  void SetUp() override {
    ScratchDirectoryTest::SetUp();
    data_file_ = directory_ / "limb.csv";
    write_prepared_csv(testing::SyntheticLimb{}.generate(400, 9), data_file_);
  }

  Config config(const std::string& body) const {
    return Config::parse("data: {file: " + data_file_.string() + "}\n" + body, "fit.yaml");
  }

  std::filesystem::path data_file_;
};

constexpr const char* kSmallLstm =
    "model: {architecture: lstm, hidden_size: 8, layers: 1, window: 10}\n"
    "training: {epochs: 3, batch_size: 64}\n"
    "evaluation: {horizons_s: [2, 60]}\n"
    "seed: 4\n";

// Rows out of order leave no run of rows a window fits in: the error says where time goes back
// instead of "the data is shorter than one window".
TEST_F(FitRun, RowsOutOfOrderAreNamedByLine) {
  SequenceData data = testing::SyntheticLimb{}.generate(400, 9);
  for (int64_t t = 0; t + 1 < data.rows(); t += 2) {  // every pair swapped
    std::swap(data.time(t), data.time(t + 1));
  }
  const auto shuffled = directory_ / "shuffled.csv";
  write_prepared_csv(data, shuffled);
  const std::string message = error_message([&] {
    run_fit(FitExperiment::from_config(Config::parse(
                "data: {file: " + shuffled.string() + "}\n" + kSmallLstm, "fit.yaml")),
            directory_ / "never", true);
  });
  EXPECT_NE(message.find(shuffled.string() + ": no training window fits: its longest run of "
                                             "train rows"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("a window needs 11; time stands still or goes back"), std::string::npos)
      << message;
  EXPECT_NE(message.find("(first at " + shuffled.string() + ":4: rows out of order?)"),
            std::string::npos)
      << message;
  EXPECT_FALSE(std::filesystem::exists(directory_ / "never"));
}

TEST_F(FitRun, WritesTheRunDirectory) {
  const auto run = directory_ / "run";
  const FitResult result = run_fit(FitExperiment::from_config(config(kSmallLstm)), run, true);
  EXPECT_EQ(result.training.epochs_run, 3);
  EXPECT_EQ(result.parameters, 4 * 8 * (6 + 8 + 2) + 36);
  for (const char* name : {"config.yaml", "progress.csv", "model.tdm", "evaluation.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(run / name)) << name;
  }
  // One progress row per epoch, with the loss columns.
  std::ifstream progress(run / "progress.csv");
  std::string header, line;
  std::getline(progress, header);
  EXPECT_NE(header.find("train/val_loss"), std::string::npos);
  int rows = 0;
  while (std::getline(progress, line)) ++rows;
  EXPECT_EQ(rows, 3);
  // One-step and two horizons, two groups each.
  ASSERT_EQ(result.evaluation.size(), 3u);
  EXPECT_EQ(result.evaluation[2].horizon, 60.0);
  EXPECT_EQ(result.evaluation[0].errors.groups.size(), 2u);
  EXPECT_GT(result.evaluation[1].errors.rollouts, result.evaluation[2].errors.rollouts);
  // The model file loads on its own and matches the run's architecture.
  EXPECT_EQ(load_model(run)->spec().window, 10);
}

TEST_F(FitRun, ARunDirectoryInUseIsLeftAlone) {
  const auto run = directory_ / "used";
  std::filesystem::create_directories(run);
  std::ofstream(run / "model.tdm") << "earlier work";
  const std::string message =
      error_message([&] { run_fit(FitExperiment::from_config(config(kSmallLstm)), run, true); });
  EXPECT_NE(message.find("nothing is overwritten"), std::string::npos) << message;
  std::ifstream in(run / "model.tdm");
  std::string kept;
  std::getline(in, kept);
  EXPECT_EQ(kept, "earlier work");
}

TEST_F(FitRun, FineTuningStartsFromTheLoadedWeights) {
  const auto first = directory_ / "first";
  run_fit(FitExperiment::from_config(config(kSmallLstm)), first, true);
  // With a zero learning rate the fine-tuned model is exactly the model it started from.
  const auto tuned = directory_ / "tuned";
  run_fit(FitExperiment::from_config(config("init_from: " + first.string() +
                                            "\ntraining: {epochs: 1, learning_rate: 0}\n"
                                            "seed: 99\n")),
          tuned, true);
  const std::unique_ptr<Model> a = load_model(first), b = load_model(tuned);
  const auto pa = a->network().parameters(), pb = b->network().parameters();
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i) EXPECT_TRUE(torch::equal(pa[i], pb[i]));
  // A model trained from scratch with that seed starts elsewhere.
  const Model fresh(a->description(), 99);
  EXPECT_FALSE(torch::equal(const_cast<Model&>(fresh).network().parameters()[0], pa[0]));
}

TEST_F(FitRun, SameConfigAndSeedGiveTheSameModelFile) {
  auto bytes = [](const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const FitExperiment experiment = FitExperiment::from_config(config(kSmallLstm));
  run_fit(experiment, directory_ / "a", true);
  run_fit(experiment, directory_ / "b", true);
  EXPECT_EQ(bytes(directory_ / "a" / "model.tdm"), bytes(directory_ / "b" / "model.tdm"));
  EXPECT_EQ(bytes(directory_ / "a" / "evaluation.csv"), bytes(directory_ / "b" / "evaluation.csv"));
  Config other_seed = config(kSmallLstm);
  other_seed.set("seed", "5");
  run_fit(FitExperiment::from_config(other_seed), directory_ / "c", true);
  EXPECT_NE(bytes(directory_ / "a" / "model.tdm"), bytes(directory_ / "c" / "model.tdm"));
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// progress.csv without its wall-time columns (time/fps, time/time_elapsed).
std::string progress_without_times(const std::filesystem::path& run) {
  std::istringstream lines(file_text(run / "progress.csv"));
  std::string header;
  std::getline(lines, header);
  std::vector<bool> keep;
  std::stringstream names(header);
  for (std::string name; std::getline(names, name, ',');) {
    keep.push_back(name != "time/fps" && name != "time/time_elapsed");
  }
  std::string kept;
  const auto keep_cells = [&](const std::string& row) {
    std::stringstream cells(row);
    std::size_t column = 0;
    for (std::string cell; std::getline(cells, cell, ','); ++column) {
      if (column < keep.size() && keep[column]) kept += cell + ",";
    }
    kept += "\n";
  };
  keep_cells(header);
  for (std::string row; std::getline(lines, row);) keep_cells(row);
  return kept;
}

// A fit stopped by Ctrl-C at an epoch's end and continued by resume_fit leaves the files of the
// uninterrupted fit: the same model bytes, the same rows, the same evaluation.
TEST_F(FitRun, AStoppedFitResumesToTheUninterruptedFilesExactly) {
  const FitExperiment experiment = FitExperiment::from_config(
      config("model: {architecture: lstm, hidden_size: 8, layers: 1, window: 10}\n"
             "training: {epochs: 4, batch_size: 64}\n"
             "evaluation: {horizons_s: [2]}\nseed: 6\n"));
  const auto whole = directory_ / "whole", stopped = directory_ / "stopped";
  run_fit(experiment, whole, true);

  request_interrupt(SIGINT);  // seen at the end of the first epoch
  const FitResult first = run_fit(experiment, stopped, true);
  clear_interrupt();
  EXPECT_EQ(first.training.interrupted, SIGINT);
  EXPECT_EQ(first.training.epochs_run, 1);
  EXPECT_TRUE(is_stopped_fit(stopped));
  EXPECT_FALSE(std::filesystem::exists(stopped / "evaluation.csv"));

  const FitResult rest = resume_fit(stopped, true);
  EXPECT_EQ(rest.training.interrupted, 0);
  EXPECT_EQ(rest.training.epochs_run, 4);
  EXPECT_FALSE(is_stopped_fit(stopped));
  EXPECT_EQ(file_text(stopped / "model.tdm"), file_text(whole / "model.tdm"));
  EXPECT_EQ(file_text(stopped / "evaluation.csv"), file_text(whole / "evaluation.csv"));
  EXPECT_EQ(progress_without_times(stopped), progress_without_times(whole));

  // A finished fit has nothing to continue.
  EXPECT_NE(error_message([&] { resume_fit(whole, true); }).find("has no fit checkpoint"),
            std::string::npos);
}

TEST(FitConfigs, EveryShippedConfigReads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(TENDRIL_CONFIG_DIR) / "dynamics")) {
    SCOPED_TRACE(entry.path().string());
    const FitExperiment e = FitExperiment::from_config(Config::load_file(entry.path()));
    EXPECT_GT(e.training.epochs, 0);
    ++count;
  }
  EXPECT_EQ(count, 11);  // 4 architectures × (default, thesis), fine-tune, scratch, seed 002
}

TEST_F(FitRun, ConfigErrorsNameTheKey) {
  EXPECT_NE(error_message([&] {
              FitExperiment::from_config(config(std::string(kSmallLstm) + "trainig: {}\n"));
            }).find("trainig"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              FitExperiment::from_config(config("init_from: x\nmodel: {architecture: lstm}\n"));
            }).find("fine-tuning keeps the architecture"),
            std::string::npos);
  EXPECT_NE(
      error_message([&] { FitExperiment::from_config(config("seed: 1\n")); }).find("needs model:"),
      std::string::npos);
  EXPECT_NE(error_message([&] {
              FitExperiment::from_config(config("model: {architecture: lstm, hiden_size: 3}\n"));
            }).find("hiden_size"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::dynamics
