#include "tendril/rl/algorithm.hpp"

#include <algorithm>

#include "tendril/core/error.hpp"
#include "tendril/envs/vector/vec_normalize.hpp"

namespace tendril::rl {

namespace {

constexpr int64_t kCheckpointFormat = 3;  // 3: archive container, vector-env snapshots

bool same_space(const Space& a, const Space& b) {
  if (a.kind() != b.kind() || a.size() != b.size()) return false;
  return a.is_discrete() ? a.n() == b.n() : a.low() == b.low() && a.high() == b.high();
}

}  // namespace

Algorithm::Algorithm(std::string name, envs::VecEnv& env, uint64_t seed)
    : name_(std::move(name)),
      env_(env),
      seed_(seed),
      action_rng_(seed, static_cast<uint64_t>(Stream::kActions)),
      update_rng_(seed, static_cast<uint64_t>(Stream::kUpdates)),
      predict_rng_(seed, static_cast<uint64_t>(Stream::kPredict)),
      env_seed_rng_(seed, static_cast<uint64_t>(Stream::kEnvSeeds)) {
  require(env.observation_space().is_box(),
          name_ + " needs Box observations, not " + env.observation_space().describe(), name_);
}

Rng& Algorithm::stream(Stream purpose) {
  switch (purpose) {
    case Stream::kActions:
      return action_rng_;
    case Stream::kUpdates:
      return update_rng_;
    case Stream::kPredict:
      return predict_rng_;
    case Stream::kEnvSeeds:
      return env_seed_rng_;
    case Stream::kInit:
      break;
  }
  throw Error("the initialisation stream is drawn afresh with init_stream()", name_);
}

void Algorithm::learn(int64_t total_timesteps, const Observers& observers) {
  total_timesteps_ = std::max<int64_t>(total_timesteps, 1);
  run(total_timesteps, observers);
}

void Algorithm::learn(int64_t total_timesteps,
                      const std::function<bool(const Progress&)>& on_iteration) {
  IterationCallback callback(on_iteration);
  learn(total_timesteps, Observers{&callback});
}

void Algorithm::set_step_counters(int64_t timesteps, int64_t total_timesteps) {
  require(timesteps >= 0 && total_timesteps > 0,
          "step counters must be non-negative, the budget positive", name_);
  num_timesteps_ = timesteps;
  total_timesteps_ = total_timesteps;
}

double Algorithm::progress_remaining() const {
  const double done = static_cast<double>(num_timesteps_) / static_cast<double>(total_timesteps_);
  return std::clamp(1.0 - done, 0.0, 1.0);
}

const envs::BatchMatrix& Algorithm::current_observations() {
  if (needs_reset_) {
    last_observations_ = env_.reset(env_seed_rng_.next_u64());
    needs_reset_ = false;
  }
  return last_observations_;
}

const envs::VecStep& Algorithm::step_environments(const envs::BatchMatrix& actions,
                                                  const Observers& observers) {
  const envs::VecStep& step = env_.step(actions);
  num_timesteps_ += env_.num_envs();
  episodes_.record(step);
  if (!observers.empty()) {
    const StepEvent event{last_observations_, actions, step, num_timesteps_};
    for (Observer* observer : observers) observer->on_step(event);
  }
  last_observations_ = step.observations;
  return step;
}

bool Algorithm::finish_iteration(Progress& progress, const Observers& observers) {
  ++iterations_;
  progress.timesteps = num_timesteps_;
  progress.iterations = iterations_;
  episodes_.report(progress);
  bool keep_going = true;
  for (Observer* observer : observers) keep_going = observer->on_iteration(progress) && keep_going;
  return keep_going;
}

envs::BatchMatrix Algorithm::predict(const envs::BatchMatrix& observations, bool deterministic) {
  envs::BatchMatrix actions;
  policy().act(observations, deterministic, predict_rng_, actions);
  return actions;
}

Action Algorithm::predict(const Observation& observation, bool deterministic) {
  return policy().act(observation, deterministic, predict_rng_);
}

void Algorithm::save_policy(const std::filesystem::path& file) const {
  std::optional<ObservationNormalization> normalization = policy().observation_normalization();
  const envs::VecNormalize* normalizer = env_.normalizer();
  if (normalizer != nullptr && normalizer->options().normalize_observation) {
    normalization = ObservationNormalization{normalizer->observation_statistics(),
                                             normalizer->options().clip_observation,
                                             normalizer->options().epsilon};
  }
  policy().save(file, normalization);
}

bool Algorithm::checkpoints_hold_environments() const {
  return !needs_reset_ && env_.supports_snapshots();
}

void Algorithm::save(const std::filesystem::path& file, const Labels& labels,
                     const ExtraWriter& extra) const {
  ArchiveWriter writer = checkpoint_writer(labels);
  if (extra) extra(writer);
  writer.commit(file);
}

std::string Algorithm::checkpoint_bytes() const { return checkpoint_writer({}).serialize(); }

void Algorithm::load(const std::filesystem::path& file, const Labels& expected,
                     const ExtraReader& read_extra) {
  load_checkpoint(ArchiveReader(file, "checkpoint"), expected, read_extra);
}

void Algorithm::warm_start(const std::filesystem::path& file) {
  const ArchiveReader reader(file, "checkpoint");
  check_checkpoint_fits(reader);
  const std::function<void()> install_state = read_state(reader);
  install_state();
}

void Algorithm::load_checkpoint_bytes(std::string bytes, const std::string& name) {
  load_checkpoint(ArchiveReader::from_bytes(std::move(bytes), "checkpoint", name), {}, {});
}

ArchiveWriter Algorithm::checkpoint_writer(const Labels& labels) const {
  ArchiveWriter writer("checkpoint");
  for (const auto& [key, value] : labels) writer.put("label/" + key, value);
  writer.put("format", kCheckpointFormat);
  writer.put("algorithm", name_);
  write_space(writer, "observation_space", env_.observation_space());
  write_space(writer, "action_space", env_.action_space());
  writer.put_rng("rng_actions", action_rng_);
  writer.put_rng("rng_updates", update_rng_);
  writer.put_rng("rng_predict", predict_rng_);
  writer.put_rng("rng_env_seeds", env_seed_rng_);
  writer.put("num_timesteps", num_timesteps_);
  writer.put("iterations", iterations_);
  episodes_.save(writer);
  const bool with_envs = checkpoints_hold_environments();
  Snapshot vec_env;
  SnapshotWriter vec_env_writer(vec_env);
  env_.save_state(vec_env_writer, with_envs);
  writer.put_bytes("vec_env", vec_env);
  if (with_envs) {
    writer.put_floats("last_observations",
                      std::span<const float>(last_observations_.data(),
                                             static_cast<std::size_t>(last_observations_.size())));
  }
  write_state(writer);
  return writer;
}

void Algorithm::check_checkpoint_fits(const ArchiveReader& reader, const Labels& expected) const {
  const std::string& where = reader.name();
  const int64_t format = reader.get_int("format");
  if (format != kCheckpointFormat) {
    throw Error("checkpoint format " + std::to_string(format) +
                    " is not supported (this build reads " + std::to_string(kCheckpointFormat) +
                    "; checkpoints of older builds cannot be resumed)",
                where);
  }
  for (const auto& [key, value] : expected) {
    require(reader.contains("label/" + key),
            "has no " + key + " label (written outside a run, or by an older build)", where);
    const std::string stored = reader.get_string("label/" + key);
    require(stored == value,
            "belongs elsewhere: its " + key + " label is " + stored + ", this one's " + value,
            where);
  }
  const std::string algorithm = reader.get_string("algorithm");
  require(algorithm == name_, "checkpoint of " + algorithm + ", not " + name_, where);
  const Space observations = read_space(reader, "observation_space");
  const Space actions = read_space(reader, "action_space");
  require(same_space(observations, env_.observation_space()),
          "the checkpoint's observations are " + observations.describe() + ", this run's " +
              env_.observation_space().describe(),
          where);
  require(same_space(actions, env_.action_space()),
          "the checkpoint's actions are " + actions.describe() + ", this run's " +
              env_.action_space().describe(),
          where);
}

void Algorithm::load_checkpoint(const ArchiveReader& reader, const Labels& expected,
                                const ExtraReader& read_extra) {
  const std::string& where = reader.name();
  check_checkpoint_fits(reader, expected);
  Rng action_rng = reader.get_rng("rng_actions");
  Rng update_rng = reader.get_rng("rng_updates");
  Rng predict_rng = reader.get_rng("rng_predict");
  Rng env_seed_rng = reader.get_rng("rng_env_seeds");
  const int64_t timesteps = reader.get_int("num_timesteps");
  const int64_t iterations = reader.get_int("iterations");
  require(timesteps >= 0 && iterations >= 0, "negative step counts", where);
  const std::function<void()> install_episodes = episodes_.prepare_load(reader);
  const Snapshot vec_env = reader.get_bytes("vec_env");
  envs::BatchMatrix last_observations;
  if (reader.contains("last_observations")) {
    const Eigen::VectorXf values =
        reader.get_floats("last_observations",
                          static_cast<int64_t>(env_.num_envs()) * env_.observation_space().size());
    last_observations = Eigen::Map<const envs::BatchMatrix>(values.data(), env_.num_envs(),
                                                            env_.observation_space().size());
  }
  const std::function<void()> install_state = read_state(reader);
  const std::function<void()> install_extra = read_extra ? read_extra(reader) : nullptr;

  // Every read succeeded. The vector env goes first: if its snapshot does not fit, nothing of
  // the algorithm has changed (the environments then need a reset).
  bool environments_restored = false;
  try {
    SnapshotReader vec_env_reader(vec_env);
    environments_restored = env_.load_state(vec_env_reader);
    vec_env_reader.expect_end();
  } catch (const Error& e) {
    needs_reset_ = true;
    throw Error("the vector environment's state does not fit this run: " + std::string(e.what()),
                where);
  }
  action_rng_ = action_rng;
  update_rng_ = update_rng;
  predict_rng_ = predict_rng;
  env_seed_rng_ = env_seed_rng;
  num_timesteps_ = timesteps;
  iterations_ = iterations;
  install_episodes();
  install_state();
  if (install_extra) install_extra();
  needs_reset_ = !(environments_restored && last_observations.size() > 0);
  if (!needs_reset_) last_observations_ = std::move(last_observations);
}

uint32_t Algorithm::save_replay_buffer(const std::filesystem::path& file) const {
  throw Error(name_ + " has no replay buffer", file.string());
}

void Algorithm::load_replay_buffer(const std::filesystem::path& file) {
  throw Error(name_ + " has no replay buffer", file.string());
}

}  // namespace tendril::rl
