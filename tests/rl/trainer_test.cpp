// Runs: the run directory, resume equals the uninterrupted run, bad input leaves runs intact.
#include "tendril/rl/trainer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/error_message.hpp"
#include "support/evaluation.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/scalar_log.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/training_observers.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

// Two envs under both normalizations: resuming must restore their shared statistics too.
constexpr const char* kExperiment = R"(
algorithm: ppo
env:
  id: Pendulum-v1
  n_envs: 2
  normalize_observation: true
  normalize_reward: true
algo:
  n_steps: 128
  batch_size: 64
  n_epochs: 2
  gamma: 0.9
n_timesteps: 2048
seed: 3
eval: {freq: 1024, episodes: 2}
checkpoint_freq: 1024
)";

fs::path fresh(const std::string& name) {
  const fs::path directory = fs::temp_directory_path() / ("tendril_trainer_" + name);
  fs::remove_all(directory);
  return directory;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// progress.csv without its wall-clock columns.
std::vector<std::string> deterministic_progress(const fs::path& run) {
  std::ifstream in(run / "progress.csv");
  std::string header;
  std::getline(in, header);
  std::vector<std::string> names;
  std::stringstream header_cells(header);
  for (std::string cell; std::getline(header_cells, cell, ',');) names.push_back(cell);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) {
    std::stringstream cells(line);
    std::string kept;
    std::size_t column = 0;
    for (std::string cell; std::getline(cells, cell, ','); ++column) {
      if (names[column] == "time/fps" || names[column] == "time/time_elapsed") continue;
      kept += names[column] + "=" + cell + ";";
    }
    rows.push_back(kept);
  }
  return rows;
}

Experiment experiment() { return Experiment::from_config(Config::parse(kExperiment, "test.yaml")); }

TEST(Trainer, WritesTheRunDirectory) {
  const fs::path run = fresh("layout");
  const TrainResult result = train(experiment(), run, {.stop_at = std::nullopt, .quiet = true});
  EXPECT_TRUE(result.finished);
  EXPECT_EQ(result.timesteps, 2048);
  for (const char* file : {"config.yaml", "progress.csv", "eval.csv", "model.policy"}) {
    EXPECT_TRUE(fs::exists(run / file)) << file;
  }
  EXPECT_TRUE(fs::exists(run / "checkpoints" / "step_1024.ckpt"));
  const std::string progress = read_text(run / "progress.csv");
  EXPECT_NE(progress.find("time/total_timesteps"), std::string::npos);
  EXPECT_NE(progress.find("rollout/ep_rew_mean"), std::string::npos);
  EXPECT_NE(progress.find("train/approx_kl"), std::string::npos);
  // Evaluations at 1024 steps and at the end.
  const std::string evaluations = read_text(run / "eval.csv");
  EXPECT_EQ(std::count(evaluations.begin(), evaluations.end(), '\n'), 3);
  bool has_events = false;
  for (const auto& entry : fs::directory_iterator(run)) {
    has_events |= entry.path().filename().string().rfind("events.out.tfevents.", 0) == 0;
  }
  EXPECT_TRUE(has_events);
}

// Evaluations reach TensorBoard under SB3's EvalCallback names, at the step they were made:
// eval/mean_reward as eval.csv's mean (to float precision, TensorBoard's simple_value), and
// eval/mean_ep_length; Pendulum reports no success, so no eval/success_rate.
TEST(Trainer, LogsEvaluationsToTheEventFileUnderSb3Names) {
  const fs::path run = fresh("eval_events");
  train(experiment(), run, {.stop_at = std::nullopt, .quiet = true});
  std::map<std::string, std::map<int64_t, float>> events;
  for (const auto& entry : fs::directory_iterator(run)) {
    if (entry.path().filename().string().rfind("events.out.tfevents.", 0) != 0) continue;
    for (const EventScalar& s : read_event_scalars(entry.path())) events[s.tag][s.step] = s.value;
  }
  std::ifstream in(run / "eval.csv");
  std::string line;
  std::getline(in, line);
  int rows = 0;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string timesteps, mean;
    std::getline(cells, timesteps, ',');
    std::getline(cells, mean, ',');
    const int64_t step = std::stoll(timesteps);
    ASSERT_TRUE(events["eval/mean_reward"].count(step)) << "no eval/mean_reward at " << step;
    EXPECT_EQ(events["eval/mean_reward"][step], static_cast<float>(std::stod(mean)));
    EXPECT_EQ(events["eval/mean_ep_length"][step], 200.0f);  // Pendulum's time limit
    ++rows;
  }
  EXPECT_EQ(rows, 2);  // at 1024 steps and at the end
  EXPECT_EQ(events["eval/mean_reward"].size(), 2u);
  EXPECT_EQ(events.count("eval/success_rate"), 0u);
}

// An evaluation of an env that reports success adds eval/success_rate (the fraction of
// episodes whose last info says is_success).
TEST(Trainer, EvaluationEventsCarryTheSuccessRate) {
  const fs::path run = fresh("eval_success");
  fs::create_directories(run);
  {
    ScalarLogObserver log(run, false, 0);
    envs::RunResult evaluation;
    const double returns[] = {1.0, 2.0, 6.0, 3.0};
    for (int i = 0; i < 4; ++i) {
      envs::EpisodeOutcome episode;
      episode.index = i;
      episode.episode_return = returns[i];
      episode.length = 10 * (i + 1);
      episode.final_info.set("is_success", i == 2 ? 0.0 : 1.0);
      evaluation.episodes.push_back(episode);
    }
    log.log_evaluation(5000, evaluation);
  }
  std::map<std::string, float> at_5000;
  for (const auto& entry : fs::directory_iterator(run)) {
    if (entry.path().filename().string().rfind("events.out.tfevents.", 0) != 0) continue;
    for (const EventScalar& s : read_event_scalars(entry.path())) {
      if (s.step == 5000) at_5000[s.tag] = s.value;
    }
  }
  EXPECT_EQ(at_5000["eval/mean_reward"], 3.0f);
  EXPECT_EQ(at_5000["eval/mean_ep_length"], 25.0f);
  EXPECT_EQ(at_5000["eval/success_rate"], 0.75f);
  EXPECT_EQ(at_5000.size(), 3u);
  EXPECT_FALSE(fs::exists(run / "progress.csv") &&
               read_text(run / "progress.csv").find("eval/") != std::string::npos);
}

TEST(Trainer, ResumedRunEqualsTheUninterruptedRun) {
  const fs::path whole = fresh("whole"), paused = fresh("paused");
  const TrainResult reference =
      train(experiment(), whole, {.stop_at = std::nullopt, .quiet = true});
  const TrainResult first = train(experiment(), paused, {.stop_at = 1000, .quiet = true});
  EXPECT_FALSE(first.finished);
  EXPECT_EQ(first.timesteps, 1024);
  EXPECT_EQ(latest_checkpoint(paused).filename(), "step_1024.ckpt");
  const TrainResult second = resume(paused, {.stop_at = std::nullopt, .quiet = true});
  EXPECT_TRUE(second.finished);
  EXPECT_EQ(second.final_eval_mean, reference.final_eval_mean);
  EXPECT_EQ(deterministic_progress(paused), deterministic_progress(whole));
  EXPECT_EQ(read_text(paused / "eval.csv"), read_text(whole / "eval.csv"));
}

// The rows of eval.csv as (timesteps, mean return).
std::vector<std::pair<int64_t, double>> evaluations(const fs::path& run) {
  std::ifstream in(run / "eval.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::pair<int64_t, double>> rows;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string timesteps, mean;
    std::getline(cells, timesteps, ',');
    std::getline(cells, mean, ',');
    rows.emplace_back(std::stoll(timesteps), std::stod(mean));
  }
  return rows;
}

Experiment experiment_saving_best() {
  Config config = Config::parse(kExperiment, "test.yaml");
  config.set("eval.save_best", "true");
  config.set("eval.freq", "512");
  config.set("checkpoint_freq", "512");
  return Experiment::from_config(config);
}

TEST(Trainer, SaveBestKeepsTheModelOfTheBestEvaluation) {
  const fs::path run = fresh("best");
  const TrainResult result =
      train(experiment_saving_best(), run, {.stop_at = std::nullopt, .quiet = true});
  const auto rows = evaluations(run);
  ASSERT_EQ(rows.size(), 4u);  // 512, 1024, 1536 and the end
  const auto best = *std::max_element(
      rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  ASSERT_TRUE(result.best_eval_mean.has_value());
  EXPECT_EQ(*result.best_eval_mean, best.second);  // eval.csv holds the exact value
  EXPECT_EQ(result.best_eval_timesteps, best.first);

  // best_model.policy, loaded anew (its normalization statistics inside), repeats that
  // evaluation on the raw environment.
  const Experiment e = experiment_saving_best();
  const std::unique_ptr<Policy> policy = load_policy(run / "best_model.policy");
  ASSERT_TRUE(policy->observation_normalization().has_value());
  const auto evaluation_env = envs::make(e.env.id, e.env.params);
  const envs::RunResult again =
      testing::evaluate(*policy, *evaluation_env, e.eval_episodes, e.seed + 1000003 + best.first);
  EXPECT_EQ(again.mean_return(), best.second);
}

TEST(Trainer, ResumedRunRemembersItsBestEvaluation) {
  const fs::path whole = fresh("best_whole"), paused = fresh("best_paused");
  const TrainResult reference =
      train(experiment_saving_best(), whole, {.stop_at = std::nullopt, .quiet = true});
  // Paused right after the run's best evaluation: the resumed run must remember it, not take
  // the next (worse) evaluation as its first best.
  ASSERT_LT(reference.best_eval_timesteps, 2048)
      << "the scenario needs a best evaluation before the end; change the seed of the test";
  train(experiment_saving_best(), paused,
        {.stop_at = reference.best_eval_timesteps, .quiet = true});
  const TrainResult resumed = resume(paused, {.stop_at = std::nullopt, .quiet = true});
  EXPECT_EQ(resumed.best_eval_mean, reference.best_eval_mean);
  EXPECT_EQ(resumed.best_eval_timesteps, reference.best_eval_timesteps);
  EXPECT_EQ(read_text(paused / "best_model.policy"), read_text(whole / "best_model.policy"));
}

constexpr const char* kOffPolicyExperiment = R"(
algorithm: sac
env:
  id: Pendulum-v1
  n_envs: 2
algo:
  learning_starts: 300
  batch_size: 32
  net_arch: [32, 32]
  log_interval: 250
n_timesteps: 2000
seed: 5
eval: {freq: 1000, episodes: 2}
checkpoint_freq: 1000
save_replay_buffer: true
)";

Experiment off_policy_experiment(const std::vector<std::pair<std::string, std::string>>& set = {}) {
  Config config = Config::parse(kOffPolicyExperiment, "sac.yaml");
  for (const auto& [key, value] : set) config.set(key, value);
  return Experiment::from_config(config);
}

TEST(Trainer, ResumedOffPolicyRunWithItsReplayBufferEqualsTheUninterruptedRun) {
  const fs::path whole = fresh("sac_whole"), paused = fresh("sac_paused");
  const TrainResult reference =
      train(off_policy_experiment(), whole, {.stop_at = std::nullopt, .quiet = true});
  const TrainResult first =
      train(off_policy_experiment(), paused, {.stop_at = 1000, .quiet = true});
  EXPECT_EQ(first.timesteps, 1000);
  EXPECT_TRUE(fs::exists(paused / "checkpoints" / "step_1000.buffer"));
  const TrainResult second = resume(paused, {.stop_at = std::nullopt, .quiet = true});
  EXPECT_TRUE(second.finished);
  EXPECT_EQ(second.final_eval_mean, reference.final_eval_mean);
  EXPECT_EQ(deterministic_progress(paused), deterministic_progress(whole));
  EXPECT_EQ(read_text(paused / "eval.csv"), read_text(whole / "eval.csv"));
  EXPECT_NE(read_text(whole / "progress.csv").find("train/ent_coef"), std::string::npos);
}

// Without its buffer a resumed off-policy run starts learning again from nothing: it says so.
TEST(Trainer, ResumingWithoutTheReplayBufferWarns) {
  const fs::path run = fresh("sac_no_buffer");
  train(off_policy_experiment({{"save_replay_buffer", "false"}}), run,
        {.stop_at = 1000, .quiet = true});
  EXPECT_FALSE(fs::exists(run / "checkpoints" / "step_1000.buffer"));
  ::testing::internal::CaptureStderr();
  resume(run, {.stop_at = 1500, .quiet = true});
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(log.find("empty replay buffer"), std::string::npos) << log;

  const fs::path kept = fresh("sac_buffer_kept");
  train(off_policy_experiment(), kept, {.stop_at = 1000, .quiet = true});
  ::testing::internal::CaptureStderr();
  resume(kept, {.stop_at = 1500, .quiet = true});
  EXPECT_EQ(::testing::internal::GetCapturedStderr().find("empty replay buffer"),
            std::string::npos);
}

TEST(Trainer, CorruptReplayBufferIsReportedAndLeftAlone) {
  const fs::path run = fresh("sac_corrupt");
  train(off_policy_experiment(), run, {.stop_at = 1000, .quiet = true});
  const fs::path buffer = run / "checkpoints" / "step_1000.buffer";
  std::string bytes = read_text(buffer);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x40);
  std::ofstream(buffer, std::ios::binary | std::ios::trunc) << bytes;
  const std::string progress = read_text(run / "progress.csv");
  const std::string message =
      testing::error_message([&] { resume(run, {.stop_at = std::nullopt, .quiet = true}); });
  EXPECT_NE(message.find("checksum"), std::string::npos) << message;
  EXPECT_EQ(read_text(buffer), bytes);
  EXPECT_EQ(read_text(run / "progress.csv"), progress);
}

// Checkpoints every 500 steps: the newest two keep their replay buffers, so a resume can fall
// back one checkpoint and still compute what the uninterrupted run computes.
TEST(Trainer, ResumeFallsBackPastANewestCheckpointWhoseReplayBufferIsCorrupt) {
  const std::vector<std::pair<std::string, std::string>> every_500 = {{"checkpoint_freq", "500"}};
  const fs::path whole = fresh("sac_whole_500"), paused = fresh("sac_fallback");
  const TrainResult reference =
      train(off_policy_experiment(every_500), whole, {.stop_at = std::nullopt, .quiet = true});
  train(off_policy_experiment(every_500), paused, {.stop_at = 1500, .quiet = true});
  const fs::path folder = paused / "checkpoints";
  EXPECT_FALSE(fs::exists(folder / "step_500.buffer"));
  ASSERT_TRUE(fs::exists(folder / "step_1000.buffer"));
  const fs::path newest = folder / "step_1500.buffer";
  std::string bytes = read_text(newest);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x40);
  std::ofstream(newest, std::ios::binary | std::ios::trunc) << bytes;

  const TrainResult resumed = resume(paused, {.stop_at = std::nullopt, .quiet = true});
  EXPECT_TRUE(resumed.finished);
  EXPECT_EQ(resumed.final_eval_mean, reference.final_eval_mean);
  EXPECT_EQ(read_text(paused / "model.policy"), read_text(whole / "model.policy"));
  EXPECT_EQ(deterministic_progress(paused), deterministic_progress(whole));
  EXPECT_TRUE(fs::exists(folder / "step_1500.ckpt.corrupt"));
}

TEST(Trainer, ResumeNeverPairsACheckpointWithAnotherRunsOrCheckpointsFiles) {
  const fs::path run = fresh("sac_own"), other = fresh("sac_other");
  train(off_policy_experiment({{"checkpoint_freq", "500"}}), run, {.stop_at = 1000, .quiet = true});
  train(off_policy_experiment({{"checkpoint_freq", "500"}, {"seed", "6"}}), other,
        {.stop_at = 1000, .quiet = true});
  const fs::path folder = run / "checkpoints";
  // The newest checkpoint with the older one's buffer (same shapes, valid file): refused by
  // its label; the resume falls back to step_500 and its own buffer.
  fs::copy_file(folder / "step_500.buffer", folder / "step_1000.buffer",
                fs::copy_options::overwrite_existing);
  const TrainResult fallen_back = resume(run, {.stop_at = 1000, .quiet = true});
  EXPECT_EQ(fallen_back.timesteps, 1000);
  EXPECT_TRUE(fs::exists(folder / "step_1000.ckpt.corrupt"));

  // Another run's checkpoint and buffer of the same shapes: refused as belonging elsewhere.
  for (const char* name : {"step_1000.ckpt", "step_1000.buffer"}) {
    fs::copy_file(other / "checkpoints" / name, folder / name,
                  fs::copy_options::overwrite_existing);
  }
  fs::remove(folder / "step_500.ckpt");
  const std::string message =
      testing::error_message([&] { resume(run, {.stop_at = std::nullopt, .quiet = true}); });
  EXPECT_NE(message.find("belongs elsewhere: its run label"), std::string::npos) << message;
}

// The recorded evaluation episodes of a run: file name → (frames, return), ordered by name.
std::map<std::string, std::pair<std::size_t, double>> recordings(const fs::path& run) {
  std::map<std::string, std::pair<std::size_t, double>> found;
  for (const auto& entry : fs::directory_iterator(run / "episodes")) {
    const Episode episode = read_episode(entry.path());
    EXPECT_TRUE(episode.summary.has_value()) << entry.path();
    if (!episode.summary) continue;
    found[entry.path().filename().string()] = {episode.frames.size(),
                                               episode.summary->episode_return};
  }
  return found;
}

TEST(Trainer, RecordsTheFirstEpisodesOfEveryEvaluationAndKeepsOneTimelineOnResume) {
  const auto recording = [] {
    Config config = Config::parse(kExperiment, "record.yaml");
    config.set("eval.freq", "512");
    config.set("eval.episodes", "3");
    config.set("eval.record", "2");
    config.set("checkpoint_freq", "512");
    return Experiment::from_config(config);
  };
  const fs::path whole = fresh("record_whole"), paused = fresh("record_paused");
  train(recording(), whole, {.stop_at = std::nullopt, .quiet = true});
  const auto recorded = recordings(whole);
  // Evaluations at 512, 1024 and 1536, and the final one at 2048: two episodes each, of the
  // 200-step time limit (the first frame is the reset).
  ASSERT_EQ(recorded.size(), 8u);
  for (const int64_t steps : {512, 1024, 1536, 2048}) {
    for (const char* number : {"_0000.tep", "_0001.tep"}) {
      const std::string name = "eval_" + std::to_string(steps) + number;
      ASSERT_EQ(recorded.count(name), 1u) << name;
      EXPECT_EQ(recorded.at(name).first, 201u) << name;
    }
  }
  // A process killed after evaluating at 1536 but before that step's checkpoint (here: the
  // checkpoint removed, and a recording cut short): its recordings past the checkpoint at 1024
  // are dropped with its eval.csv rows, then made again.
  train(recording(), paused, {.stop_at = 1536, .quiet = true});
  fs::remove(paused / "checkpoints" / "step_1536.ckpt");
  std::ofstream(paused / "episodes" / "eval_1536_0002.tep") << "cut short by a kill";
  resume(paused, {.stop_at = std::nullopt, .quiet = true});
  EXPECT_EQ(recordings(paused), recorded);
  EXPECT_EQ(read_text(paused / "eval.csv"), read_text(whole / "eval.csv"));
}

TEST(Experiment, RecordingMoreEpisodesThanAnEvaluationRunsIsRejected) {
  Config config = Config::parse(kExperiment, "record.yaml");
  config.set("eval.record", "3");
  const std::string message = testing::error_message([&] { Experiment::from_config(config); });
  EXPECT_NE(message.find("record.yaml: eval.record"), std::string::npos) << message;
}

TEST(Trainer, ExistingRunIsNeverOverwritten) {
  const fs::path run = fresh("occupied");
  fs::create_directories(run);
  std::ofstream(run / "notes.txt") << "keep me";
  EXPECT_THROW(train(experiment(), run, {.stop_at = std::nullopt, .quiet = true}), Error);
  EXPECT_EQ(read_text(run / "notes.txt"), "keep me");
  EXPECT_EQ(std::distance(fs::directory_iterator(run), fs::directory_iterator()), 1);
}

TEST(Trainer, CorruptCheckpointIsReportedAndLeftAlone) {
  const fs::path run = fresh("corrupt");
  train(experiment(), run, {.stop_at = 1000, .quiet = true});
  const fs::path checkpoint = latest_checkpoint(run);
  const std::string bytes = read_text(checkpoint);
  std::ofstream(checkpoint, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const std::string truncated = read_text(checkpoint);
  const std::string progress = read_text(run / "progress.csv");
  EXPECT_THROW(resume(run, {.stop_at = std::nullopt, .quiet = true}), Error);
  EXPECT_EQ(read_text(checkpoint), truncated);
  EXPECT_EQ(read_text(run / "progress.csv"), progress);
}

std::string error_of(const std::string& yaml) {
  const std::string message =
      testing::error_message([&] { Experiment::from_config(Config::parse(yaml, "bad.yaml")); });
  return message == "no error" ? "accepted" : message;
}

TEST(Experiment, BadFilesAreRejectedByName) {
  const std::string base = "algorithm: ppo\nenv: {id: Pendulum-v1}\nn_timesteps: 100\n";
  EXPECT_EQ(error_of(base), "accepted");
  // The environment's own parameters are keys of the file too.
  EXPECT_EQ(
      error_of("algorithm: sac\nenv: {id: Pendulum-v1, params: {g: 9.81, max_episode_steps: 50}}\n"
               "n_timesteps: 100\n"),
      "accepted");
  EXPECT_EQ(error_of(base + "n_envs: 4\n"), "bad.yaml: unknown key 'n_envs'");
  EXPECT_NE(error_of("algorithm: a2c\nenv: {id: Pendulum-v1}\nn_timesteps: 1\n")
                .find("unknown algorithm 'a2c'"),
            std::string::npos);
  // An algorithm that cannot act in the environment's action space fails before any run starts.
  EXPECT_NE(error_of("algorithm: dqn\nenv: {id: Pendulum-v1}\nn_timesteps: 1\n").find("Discrete"),
            std::string::npos);
  EXPECT_NE(
      error_of("algorithm: ppo\nenv: {id: Pendulum-v9}\nn_timesteps: 1\n").find("'Pendulum-v9'"),
      std::string::npos);
  EXPECT_NE(error_of(base + "algo: {batch_size: many}\n").find("algo.batch_size"),
            std::string::npos);
  EXPECT_NE(error_of(base + "algo: {learning_rat: 0.1}\n").find("algo.learning_rat"),
            std::string::npos);
  EXPECT_NE(
      error_of("algorithm: ppo\nenv: {id: Pendulum-v1, params: {gravity: 3}}\nn_timesteps: 1\n")
          .find("env.params.gravity"),
      std::string::npos);
  EXPECT_NE(
      error_of("algorithm: ppo\nenv: {id: Pendulum-v1\nn_timesteps: 1\n").find("malformed YAML"),
      std::string::npos);
}

}  // namespace
}  // namespace tendril::rl
