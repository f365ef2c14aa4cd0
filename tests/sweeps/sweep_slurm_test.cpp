#include "tendril/sweeps/sweep_slurm.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/scratch_directory.hpp"

namespace tendril::sweeps {
namespace {

namespace fs = std::filesystem;

class SlurmScripts : public testing::ScratchDirectoryTest {
 protected:
  SlurmScripts() : ScratchDirectoryTest("sweep_slurm") {}
  Sweep sweep() const {
    std::ofstream(directory_ / "base.yaml")
        << "algorithm: ppo\nenv: {id: Pendulum-v1, n_envs: 3}\nalgo: {n_steps: 64}\n"
           "n_timesteps: 1000\nseed: 0\n";
    std::ofstream(directory_ / "grid.yaml")
        << "experiment: base.yaml\ngrid:\n  - {key: algo.n_steps, values: [64, 128]}\n"
           "  - {key: seed, values: [0, 1, 2]}\noutput: runs/sweeps/grid\n";
    return Sweep::load(directory_ / "grid.yaml");
  }
  SlurmOptions options() const {
    SlurmOptions o;
    o.tendril = "/opt/tendril/bin/tendril";
    o.sweep_file = "/home/me/configs/it's/grid.yaml";
    o.working_directory = "/scratch/me";
    return o;
  }
};

// The lines of `text` that start with `prefix`.
std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end - at);
    if (line.rfind(prefix, 0) == 0) found.push_back(line);
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return found;
}

TEST_F(SlurmScripts, OneArrayTaskPerRunByDefault) {
  const std::string script = slurm_script(sweep(), options());
  EXPECT_EQ(script.rfind("#!/bin/bash\n", 0), 0u);
  EXPECT_EQ(lines_starting(script, "#SBATCH --array="),
            std::vector<std::string>{"#SBATCH --array=0-5"});
  EXPECT_EQ(lines_starting(script, "#SBATCH --cpus-per-task="),
            std::vector<std::string>{"#SBATCH --cpus-per-task=3"});  // the runs' n_envs
  EXPECT_EQ(lines_starting(script, "#SBATCH --time="),
            std::vector<std::string>{"#SBATCH --time=24:00:00"});
  EXPECT_EQ(lines_starting(script, "#SBATCH --job-name="),
            std::vector<std::string>{"#SBATCH --job-name=tendril-grid"});
  EXPECT_EQ(
      lines_starting(script, "#SBATCH --output="),
      std::vector<std::string>{"#SBATCH --output=/scratch/me/runs/sweeps/grid/slurm/%A_%a.out"});
  // SIGTERM five minutes before the time limit, to tendril itself (exec): a clean checkpoint.
  EXPECT_EQ(lines_starting(script, "#SBATCH --signal="),
            std::vector<std::string>{"#SBATCH --signal=B:TERM@300"});
  EXPECT_TRUE(lines_starting(script, "#SBATCH --partition").empty());
  EXPECT_TRUE(lines_starting(script, "#SBATCH --mem").empty());
  EXPECT_EQ(lines_starting(script, "cd "), std::vector<std::string>{"cd '/scratch/me'"});
  // The sweep file's apostrophe survives bash's quoting.
  EXPECT_EQ(lines_starting(script, "exec "),
            std::vector<std::string>{"exec '/opt/tendril/bin/tendril' sweep run "
                                     "'/home/me/configs/it'\\''s/grid.yaml' --rank "
                                     "\"$SLURM_ARRAY_TASK_ID\" --ranks 6 --quiet"});
  // Every #SBATCH line comes before the first command (sbatch stops reading them there).
  EXPECT_LT(script.rfind("#SBATCH"), script.find("\nset -euo pipefail"));
}

TEST_F(SlurmScripts, FewerTasksShareTheRunsAndResourcesAreOptions) {
  SlurmOptions o = options();
  o.tasks = 4;
  o.max_running = 2;
  o.cpus_per_task = 8;
  o.time = "2-00:00:00";
  o.mem = "16G";
  o.partition = "cpu";
  o.account = "lab";
  o.job_name = "batch";
  o.stop_before = 0;
  const std::string script = slurm_script(sweep(), o);
  EXPECT_EQ(lines_starting(script, "#SBATCH --array="),
            std::vector<std::string>{"#SBATCH --array=0-3%2"});
  EXPECT_EQ(lines_starting(script, "exec ")
                .front()
                .substr(lines_starting(script, "exec ").front().find("--rank")),
            "--rank \"$SLURM_ARRAY_TASK_ID\" --ranks 4 --quiet");
  for (const char* line :
       {"#SBATCH --cpus-per-task=8", "#SBATCH --time=2-00:00:00", "#SBATCH --mem=16G",
        "#SBATCH --partition=cpu", "#SBATCH --account=lab", "#SBATCH --job-name=batch"}) {
    EXPECT_EQ(lines_starting(script, line).size(), 1u) << line;
  }
  EXPECT_TRUE(lines_starting(script, "#SBATCH --signal").empty());
  o.tasks = 50;  // more tasks than runs: one per run
  EXPECT_EQ(lines_starting(slurm_script(sweep(), o), "#SBATCH --array="),
            std::vector<std::string>{"#SBATCH --array=0-5%2"});
}

}  // namespace
}  // namespace tendril::sweeps
