#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/archive.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/episode_tracker.hpp"
#include "tendril/rl/observer.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::rl {

// What every learning algorithm shares (SB3's BaseAlgorithm): the vector env it trains on
// (borrowed; it must outlive the algorithm), the seed and the random streams derived from it,
// the step counters, the record of finished episodes, the observations the next step acts on,
// checkpoints, and the policy it trains. The families (on-policy, off-policy) add their loops;
// each algorithm adds its update.
//
// Randomness: one stream per purpose, all derived from the seed (Stream), so the same seed
// gives the same run, whatever the threads.
class Algorithm {
 public:
  virtual ~Algorithm() = default;
  Algorithm(const Algorithm&) = delete;
  Algorithm& operator=(const Algorithm&) = delete;

  // Trains until `total_timesteps` environment steps have been taken over all envs (calls to
  // `learn` continue the count; schedules anneal over `total_timesteps`). Observers see every
  // step and every iteration; any of them can stop training after an iteration.
  void learn(int64_t total_timesteps, const Observers& observers = {});
  void learn(int64_t total_timesteps, const std::function<bool(const Progress&)>& on_iteration);

  // The policy being trained: it acts on the observations this algorithm sees (normalized
  // ones behind a VecNormalize).
  virtual const Policy& policy() const = 0;
  // policy().act with the algorithm's own prediction stream (SB3's predict).
  envs::BatchMatrix predict(const envs::BatchMatrix& observations, bool deterministic);
  Action predict(const Observation& observation, bool deterministic);
  // Writes the policy's model file with the vector env's observation statistics (if it
  // normalizes observations), so that the loaded policy acts on raw observations.
  void save_policy(const std::filesystem::path& file) const;

  // A checkpoint: everything needed to resume exactly — the policy's and critics' weights,
  // optimizer states, random streams, counters, episode records and the vector env's state
  // (its normalization statistics; its environments when they all support snapshots).
  // Written atomically; `load` reads a checkpoint of the same algorithm, spaces and network
  // and changes nothing on any error. `labels` tie a checkpoint to what surrounds it (the
  // trainer's run identity and replay-buffer checksum): `load` requires every expected label to
  // be stored with the same value.
  //
  // `extra` adds the state of what trains beside the algorithm (rl/run_companion) to the same
  // file; `read_extra` reads it back and returns the action that installs it (run after the
  // algorithm's own state is installed).
  using Labels = std::vector<std::pair<std::string, std::string>>;
  using ExtraWriter = std::function<void(ArchiveWriter&)>;
  using ExtraReader = std::function<std::function<void()>(const ArchiveReader&)>;
  void save(const std::filesystem::path& file, const Labels& labels = {},
            const ExtraWriter& extra = {}) const;
  void load(const std::filesystem::path& file, const Labels& expected = {},
            const ExtraReader& read_extra = {});
  // A warm start (seed 003 trains case 3 from its case-2 model): installs the learned state of
  // another run's checkpoint of the same algorithm, spaces and network — weights, target
  // networks, optimizer moments, the entropy coefficient — and keeps this run's own step
  // counters, random streams, episode records, environments and (empty) replay buffer, as
  // Stable-Baselines3's load-then-learn on a new environment does. Changes nothing on any error.
  void warm_start(const std::filesystem::path& file);
  // A checkpoint as bytes and back, for one nested in another (a co-trained agent's state in
  // its run's checkpoint); `name` stands for the file in messages.
  std::string checkpoint_bytes() const;
  void load_checkpoint_bytes(std::string bytes, const std::string& name);
  // Whether the next checkpoint will hold the environments (all support snapshots and they
  // have been reset). When not, whoever checkpoints calls request_seeded_reset() right after,
  // so that a run resumed from the checkpoint (which must reset them) and the uninterrupted
  // run compute the same.
  bool checkpoints_hold_environments() const;
  // Makes the next step start from a seeded reset of every environment.
  void request_seeded_reset() { needs_reset_ = true; }

  // State too large for checkpoints, kept in a file of its own (off-policy replay buffers).
  virtual bool has_replay_buffer() const { return false; }
  // Returns the file's checksum (rl::replay_buffer_checksum reads it back from the file).
  virtual uint32_t save_replay_buffer(const std::filesystem::path& file) const;
  virtual void load_replay_buffer(const std::filesystem::path& file);

  const std::string& name() const { return name_; }
  uint64_t seed() const { return seed_; }
  int64_t num_timesteps() const { return num_timesteps_; }
  int64_t iterations() const { return iterations_; }
  // Returns of the last (up to) 100 finished episodes, oldest first.
  const std::deque<double>& recent_returns() const { return episodes_.recent_returns(); }

 protected:
  // The random streams, one per purpose.
  enum class Stream : uint64_t { kInit = 1, kActions, kUpdates, kPredict, kEnvSeeds };

  Algorithm(std::string name, envs::VecEnv& env, uint64_t seed);

  // The family's training loop: until num_timesteps() reaches `total_timesteps`, collect with
  // observe_step after every vector-env step, update, and end each iteration with
  // finish_iteration (stop when it returns false).
  virtual void run(int64_t total_timesteps, const Observers& observers) = 0;
  // The family's and the algorithm's own state in and out of checkpoints. `read_state` reads
  // and checks everything and returns the action that installs it (run only once every read
  // of the checkpoint succeeded).
  virtual void write_state(ArchiveWriter& writer) const = 0;
  virtual std::function<void()> read_state(const ArchiveReader& reader) = 0;

  ArchiveWriter checkpoint_writer(const Labels& labels) const;
  // Raises Error unless `reader` is a checkpoint of this build's format with the `expected`
  // labels, of this algorithm and of this run's spaces.
  void check_checkpoint_fits(const ArchiveReader& reader, const Labels& expected = {}) const;
  void load_checkpoint(const ArchiveReader& reader, const Labels& expected,
                       const ExtraReader& read_extra);

  envs::VecEnv& env() { return env_; }
  const envs::VecEnv& env() const { return env_; }
  Rng& stream(Stream purpose);
  // For an algorithm that learns from steps someone else takes (a co-trained critic): the step
  // counters its schedules read (exploration, learning rates), as if its own `learn` of
  // `total_timesteps` had reached `timesteps`.
  void set_step_counters(int64_t timesteps, int64_t total_timesteps);
  Rng init_stream() const { return Rng(seed_, static_cast<uint64_t>(Stream::kInit)); }
  // The observations the next step acts on; resets every environment first (seeded from the
  // env-seed stream) when needed.
  const envs::BatchMatrix& current_observations();
  // Steps the vector env with `actions` (env units), counts the steps, records finished
  // episodes, tells the observers and makes the new observations current.
  const envs::VecStep& step_environments(const envs::BatchMatrix& actions,
                                         const Observers& observers);
  // Counts the iteration, fills `progress`'s counters and episode fields, and tells every
  // observer; false when one of them asks to stop.
  bool finish_iteration(Progress& progress, const Observers& observers);
  // 1 at the start of the current `learn`'s budget, 0 when it is spent (SB3's).
  double progress_remaining() const;

 private:
  std::string name_;
  envs::VecEnv& env_;
  uint64_t seed_;
  Rng action_rng_, update_rng_, predict_rng_, env_seed_rng_;
  int64_t num_timesteps_ = 0;
  int64_t total_timesteps_ = 1;  // of the current `learn`
  int64_t iterations_ = 0;
  EpisodeTracker episodes_;
  envs::BatchMatrix last_observations_;
  bool needs_reset_ = true;
};

}  // namespace tendril::rl
