#include "tendril/envs/wrappers/episode_recorder.hpp"

#include <cstdio>

#include "tendril/core/error.hpp"

namespace tendril::envs {

namespace {

EpisodeFrame frame_of(const Env& env) {
  EpisodeFrame frame;
  env.describe_scene(frame.scene);
  return frame;
}

}  // namespace

EpisodeTap::EpisodeTap(RecordingOptions options) : options_(std::move(options)) {
  require(!options_.directory.empty(), "no directory to record episodes into", "EpisodeTap");
  std::filesystem::create_directories(options_.directory);
}

std::filesystem::path EpisodeTap::next_file() {
  while (true) {
    char name[32];
    std::snprintf(name, sizeof name, "_%04d.tep", next_index_++);
    const std::filesystem::path file = options_.directory / (options_.prefix + name);
    if (!std::filesystem::exists(file)) return file;
  }
}

void EpisodeTap::started(const Env& env, std::optional<uint64_t> seed) {
  writer_.reset();  // an episode cut off by this reset stays incomplete
  if (options_.max_episodes > 0 && started_ >= options_.max_episodes) return;
  ++started_;
  EpisodeMetadata metadata = options_.metadata;
  if (seed) metadata.emplace_back("reset_seed", std::to_string(*seed));
  writer_ = std::make_unique<EpisodeWriter>(next_file(), metadata,
                                            static_cast<int>(env.action_space().size()));
  writer_->write(frame_of(env));
}

void EpisodeTap::stepped(const Env& env, const Action& action, const Step& step) {
  require(writer_ != nullptr || started_ > 0, "step recorded before a reset", "EpisodeTap");
  if (writer_ == nullptr) return;  // past max_episodes, or the episode has ended
  EpisodeFrame frame = frame_of(env);
  frame.step = writer_->frames();
  frame.reward = step.reward;
  frame.terminated = step.terminated;
  frame.truncated = step.truncated;
  frame.action = action;
  frame.info = step.info.entries();
  writer_->write(frame);
  if (step.terminated || step.truncated) {
    const EpisodeSummary summary = writer_->finish();
    episodes_.push_back({writer_->file(), summary});
    writer_.reset();
  }
}

EpisodeRecorder::EpisodeRecorder(std::unique_ptr<Env> inner, RecordingOptions options)
    : Wrapper(std::move(inner)), tap_(std::move(options)) {}

Observation EpisodeRecorder::reset(std::optional<uint64_t> seed) {
  Observation observation = inner_->reset(seed);
  tap_.started(*inner_, seed);
  return observation;
}

Step EpisodeRecorder::step(const Action& action) {
  Step result = inner_->step(action);
  tap_.stepped(*inner_, action, result);
  return result;
}

std::vector<RecordedEpisode> record_episodes(Env& env,
                                             const std::function<Action(const Observation&)>& act,
                                             int episodes, uint64_t seed,
                                             const RecordingOptions& options) {
  require(episodes >= 1, "record at least one episode", "record_episodes");
  EpisodeTap tap(options);
  for (int e = 0; e < episodes; ++e) {
    const std::optional<uint64_t> reset_seed =
        e == 0 ? std::optional<uint64_t>(seed) : std::nullopt;
    Observation observation = env.reset(reset_seed);
    tap.started(env, reset_seed);
    while (true) {
      const Action action = act(observation);
      Step step = env.step(action);
      tap.stepped(env, action, step);
      if (step.terminated || step.truncated) break;
      observation = std::move(step.observation);
    }
  }
  return tap.episodes();
}

}  // namespace tendril::envs
