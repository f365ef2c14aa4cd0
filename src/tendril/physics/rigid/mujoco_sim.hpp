#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "tendril/core/snapshot.hpp"

// MuJoCo's types, declared here so that users of this header need not see MuJoCo's headers;
// only physics/rigid's sources include <mujoco/mujoco.h>.
struct mjModel_;
struct mjData_;

namespace tendril::physics {

// A compiled MuJoCo model (immutable, shared between copies) with its own simulation state
// (mjData), in the spirit of MuJoCo's own split of mjModel and mjData.
//
// Errors: a model MuJoCo cannot parse or compile raises tendril::Error carrying MuJoCo's message
// and the file (or name) it came from. MuJoCo's fatal errors (mju_error) raise tendril::Error
// instead of ending the process, and its warnings go to tendril's log; see install_handlers.
//
// Snapshots hold what mj_step reads of mjData and nothing else — time, qpos, qvel, act,
// qacc_warmstart (the constraint solver's warm start), ctrl, qfrc_applied, xfrc_applied — so that
// stepping on after load_state repeats the original bit for bit. (MuJoCo 2.2.2 has no
// mj_getState; this is the same selection as its later mjSTATE_INTEGRATION.)
class MujocoSim {
 public:
  // Compiles MJCF text; `name` labels errors (e.g. "UR5/Reach-v0 model").
  static MujocoSim from_xml(std::string_view mjcf, std::string_view name);
  // Loads an MJCF (or URDF) file; a missing, unreadable or invalid file raises Error naming it.
  static MujocoSim from_file(const std::filesystem::path& file);

  MujocoSim(const MujocoSim& other);
  MujocoSim& operator=(const MujocoSim& other);
  MujocoSim(MujocoSim&&) noexcept = default;
  MujocoSim& operator=(MujocoSim&&) noexcept = default;
  ~MujocoSim() = default;

  const mjModel_* model() const { return model_.get(); }
  mjData_* data() { return data_.get(); }
  const mjData_* data() const { return data_.get(); }
  const std::string& name() const { return name_; }

  // The id of the named element of `type` (an mjtObj value), or Error naming the element.
  int id_of(int type, std::string_view element) const;

  // Restores the model's initial state (mj_resetData) and recomputes derived quantities.
  void reset();

  void save_state(SnapshotWriter& out) const;
  // Reads everything before changing anything; a snapshot of another model size raises Error.
  void load_state(SnapshotReader& in);

  // Sets MuJoCo's error and warning hooks once per process: mju_error raises tendril::Error
  // (MuJoCo is C; its frames carry unwind tables on this platform) and warnings are logged.
  static void install_handlers();

 private:
  MujocoSim(std::shared_ptr<const mjModel_> model, std::string name);

  struct DataDeleter {
    void operator()(mjData_* data) const;
  };

  std::shared_ptr<const mjModel_> model_;
  std::unique_ptr<mjData_, DataDeleter> data_;
  std::string name_;
};

}  // namespace tendril::physics
