#include "tendril/sweeps/sweep.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/rl/experiment.hpp"

namespace tendril::sweeps {
namespace {

namespace fs = std::filesystem;

// The files go into a scratch directory of the test's own, removed afterwards.
class Sweeps : public testing::ScratchDirectoryTest {
 protected:
  Sweeps() : ScratchDirectoryTest("sweep") {}
  fs::path write_files(const std::string& name, const std::string& sweep) const;
};

fs::path Sweeps::write_files(const std::string& name, const std::string& sweep) const {
  const fs::path folder = directory_ / name;
  fs::create_directories(folder / "sweeps");
  std::ofstream(folder / "base.yaml")
      << "algorithm: ppo\nenv: {id: Pendulum-v1, n_envs: 2}\nalgo: {n_steps: 64}\n"
         "n_timesteps: 1000\nseed: 0\n";
  std::ofstream(folder / "sweeps" / "grid.yaml") << sweep;
  return folder / "sweeps" / "grid.yaml";
}

TEST_F(Sweeps, RunsAreTheGridsProductFirstKeySlowest) {
  const Sweep sweep = Sweep::load(write_files("product",
                                              "experiment: ../base.yaml\n"
                                              "grid:\n"
                                              "  - {key: algo.n_steps, values: [32, 128]}\n"
                                              "  - {key: seed, values: [0, 1, 2]}\n"
                                              "output: runs/grid\n"));
  const auto runs = sweep.runs();
  ASSERT_EQ(runs.size(), 6u);
  EXPECT_EQ(runs[0].name, "n_steps_32-seed_0");
  EXPECT_EQ(runs[2].name, "n_steps_32-seed_2");
  EXPECT_EQ(runs[3].name, "n_steps_128-seed_0");
  const rl::Experiment experiment = rl::Experiment::from_config(sweep.experiment(runs[4]));
  EXPECT_EQ(experiment.seed, 1u);
  EXPECT_EQ(experiment.algo.get<int64_t>("n_steps"), 128);
  EXPECT_EQ(experiment.env.n_envs, 2);
}

TEST_F(Sweeps, BadFilesAreRejectedByName) {
  const auto error = [this](const std::string& name, const std::string& text) {
    return testing::error_message([&] { Sweep::load(write_files(name, text)); });
  };
  EXPECT_NE(error("unknown",
                  "experiment: ../base.yaml\ngrid: [{key: seed, values: [0]}]\n"
                  "output: x\nrepeat: 2\n")
                .find("repeat"),
            std::string::npos);
  EXPECT_NE(error("badvalue",
                  "experiment: ../base.yaml\n"
                  "grid: [{key: algo.n_steps, values: [0]}]\noutput: x\n")
                .find("n_steps"),
            std::string::npos);
  EXPECT_NE(error("badkey",
                  "experiment: ../base.yaml\n"
                  "grid: [{key: algo.n_stepz, values: [8]}]\noutput: x\n")
                .find("algo.n_stepz"),
            std::string::npos);
  EXPECT_NE(error("nogrid", "experiment: ../base.yaml\ngrid: []\noutput: x\n").find("grid"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::sweeps
