#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/episode.hpp"
#include "tendril/core/episode_writer.hpp"
#include "tendril/envs/wrappers/wrapper.hpp"

namespace tendril::envs {

struct RecordingOptions {
  std::filesystem::path directory;  // created when missing
  std::string prefix = "episode";   // files <prefix>_<NNNN>.tep, the first free numbers
  EpisodeMetadata metadata;         // written into every file's header (env id, run, policy, ...)
  int max_episodes = 0;             // record only the first this many episodes; 0: all
};

struct RecordedEpisode {
  std::filesystem::path file;
  EpisodeSummary summary;
};

// Records the episodes of an environment it does not own into episode files
// (docs/episode_format.md): `started` after each reset, `stepped` after each step, which closes
// the file when the step ends the episode. Each frame holds what Env::describe_scene draws (an
// empty scene for environments that draw nothing), the action, reward and info.
class EpisodeTap {
 public:
  explicit EpisodeTap(RecordingOptions options);

  void started(const Env& env, std::optional<uint64_t> seed);
  void stepped(const Env& env, const Action& action, const Step& step);

  // Finished episodes, oldest first.
  const std::vector<RecordedEpisode>& episodes() const { return episodes_; }

 private:
  std::filesystem::path next_file();

  RecordingOptions options_;
  std::unique_ptr<EpisodeWriter> writer_;
  std::vector<RecordedEpisode> episodes_;
  int next_index_ = 0;
  int started_ = 0;
};

// Writes every episode of the environment it wraps into its own file in a directory; an episode
// cut off by a new reset stays an incomplete recording.
class EpisodeRecorder : public Wrapper {
 public:
  EpisodeRecorder(std::unique_ptr<Env> inner, RecordingOptions options);

  Observation reset(std::optional<uint64_t> seed = std::nullopt) override;
  Step step(const Action& action) override;

  const std::vector<RecordedEpisode>& episodes() const { return tap_.episodes(); }

 private:
  EpisodeTap tap_;
};

// Runs `episodes` whole episodes of `env` (which must end them, e.g. by a time limit) with
// `act` choosing each action from the observation, the first reset seeded with `seed` (as
// evaluation does), and records each into options.directory.
std::vector<RecordedEpisode> record_episodes(Env& env,
                                             const std::function<Action(const Observation&)>& act,
                                             int episodes, uint64_t seed,
                                             const RecordingOptions& options);

}  // namespace tendril::envs
