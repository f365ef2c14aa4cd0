#include "tendril/safety/constrained_experiment.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "support/same_run.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"

namespace tendril::safety {
namespace {

namespace fs = std::filesystem;

// SAC with a Lagrangian cost critic on the double integrator, small and fast.
constexpr const char* kExperiment = R"(
algorithm: sac
env: {id: Safety/DoubleIntegrator-v0, params: {horizon: 50, goal_position: 2.5}}
algo: {net_arch: [16, 16], learning_starts: 100, batch_size: 32, log_interval: 250}
n_timesteps: 1000
seed: 4
save_replay_buffer: true
eval: {episodes: 3}
constrained:
  method: lagrangian
  cost_limit: 0.1
  cost_critic: {net_arch: [16, 16], buffer_size: 2000, batch_size: 32, learning_starts: 100}
  multiplier: {initial: 1.0, learning_rate: 1.0e-2}
)";

fs::path fresh(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() /
                             ("tendril_constrained_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(directory);
  return directory;
}

// Stopped by SIGTERM and resumed, a Lagrangian run ends with the files of the run that was never
// stopped: the cost critic's weights, targets, optimizer, buffer and draws, and the multiplier
// with its optimizer, travel in the checkpoint.
TEST(ConstrainedExperiment, AnInterruptedRunResumesToTheUninterruptedRunsFiles) {
  const ConstrainedExperiment e = ConstrainedExperiment::from_config(Config::parse(kExperiment));
  rl::TrainOptions quiet;
  quiet.quiet = true;
  const fs::path whole = fresh("whole");
  const rl::TrainResult finished = train_constrained(e, whole, quiet);
  ASSERT_TRUE(finished.finished);
  ASSERT_EQ(finished.companion_scalars.size(), 3u);
  EXPECT_EQ(finished.companion_scalars[0].first, "lagrangian/multiplier");
  // The multiplier moved from its initial 1 (dual steps of 1e-2 on log ν).
  EXPECT_NE(finished.companion_scalars[0].second, 1.0);

  const fs::path stopped = fresh("stopped");
  request_interrupt(SIGTERM);  // seen at the end of the first iteration, 250 steps
  const rl::TrainResult first = train_constrained(e, stopped, quiet);
  clear_interrupt();
  EXPECT_FALSE(first.finished);
  EXPECT_EQ(first.interrupted, SIGTERM);
  EXPECT_EQ(first.timesteps, 250);
  rl::TrainOptions resumed = quiet;
  resumed.companion = constrained_baseline(e);
  ASSERT_TRUE(rl::resume(stopped, e.task, resumed).finished);
  testing::expect_same_run(stopped, whole, {"model.policy", "eval.csv"});

  // A checkpoint of a run without the cost critic (another experiment) is not resumed with one.
  fs::remove(stopped / "model.policy");
  EXPECT_THROW(rl::resume(stopped, e.task, quiet), Error);
  fs::remove_all(whole);
  fs::remove_all(stopped);
}

}  // namespace
}  // namespace tendril::safety
