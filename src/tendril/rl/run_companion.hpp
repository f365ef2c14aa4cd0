#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "tendril/core/archive.hpp"
#include "tendril/envs/vector/vec_env.hpp"
#include "tendril/rl/observer.hpp"

namespace tendril::rl {

class Algorithm;

// What a training run carries beside its algorithm (rl/trainer): a learner fed from the
// algorithm's own steps — a co-trained safety agent, a constrained baseline's cost critic and
// multiplier. It observes every step before the run's other observers, adds its scalars to
// progress.csv, travels in every checkpoint of the run (so a stopped run resumes exactly) and
// writes its own files when the run finishes.
class RunCompanion : public Observer {
 public:
  // What it is ("safety co-training"): the label that ties a checkpoint to it, so a run is
  // never resumed with another companion or without its own.
  virtual std::string name() const = 0;
  // Once, before the algorithm is made: the run's vector env comes in, the one the algorithm
  // trains on goes out (the same, or a wrapper that owns it).
  virtual std::unique_ptr<envs::VecEnv> attach(std::unique_ptr<envs::VecEnv> env) { return env; }
  // Once the algorithm exists (made on what `attach` returned).
  virtual void bind(Algorithm& /*algorithm*/) {}
  // After the algorithm's last step of this process (finished or stopped).
  virtual void unbind(Algorithm& /*algorithm*/) {}
  // Its scalars of the iteration that just ended, appended to the run's.
  virtual void add_scalars(TrainStats& /*stats*/) {}
  // Its state into the run's checkpoint, under keys of its own.
  virtual void save(ArchiveWriter& writer) const = 0;
  // Reads and checks its state from a checkpoint and returns the action that installs it (run
  // only once every read of the checkpoint succeeded).
  virtual std::function<void()> load(const ArchiveReader& reader) = 0;
  // The run reached its budget: its files beside model.policy (written before it, as
  // model.policy marks a finished run).
  virtual void finish(const std::filesystem::path& /*run_directory*/) const {}
};

using CompanionFactory = std::function<std::unique_ptr<RunCompanion>()>;

}  // namespace tendril::rl
