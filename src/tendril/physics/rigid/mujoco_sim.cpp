#include "tendril/physics/rigid/mujoco_sim.hpp"

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <array>
#include <cstring>
#include <mutex>

#include "tendril/core/error.hpp"
#include "tendril/core/log.hpp"

namespace tendril::physics {

namespace {

constexpr int kErrorSize = 1024;

// MuJoCo's XML parser keeps global state (the last parsed model), so loads are serialised.
std::mutex& load_mutex() {
  static std::mutex mutex;
  return mutex;
}

void raise_mujoco_error(const char* message) { throw Error(message, "MuJoCo"); }
void log_mujoco_warning(const char* message) { log::warning("MuJoCo: ", message); }

std::shared_ptr<const mjModel> own(mjModel* model) {
  return std::shared_ptr<const mjModel>(
      model, [](const mjModel* m) { mj_deleteModel(const_cast<mjModel*>(m)); });
}

// A virtual file system with one in-memory file, freed on every path out.
struct OneFileVfs {
  std::unique_ptr<mjVFS> vfs = std::make_unique<mjVFS>();
  OneFileVfs(const char* filename, std::string_view contents) {
    mj_defaultVFS(vfs.get());
    require(mj_makeEmptyFileVFS(vfs.get(), filename, static_cast<int>(contents.size())) == 0,
            "cannot hold the model text in MuJoCo's virtual file system", "MuJoCo");
    const int index = mj_findFileVFS(vfs.get(), filename);
    std::memcpy(vfs->filedata[index], contents.data(), contents.size());
  }
  ~OneFileVfs() { mj_deleteVFS(vfs.get()); }
  OneFileVfs(const OneFileVfs&) = delete;
  OneFileVfs& operator=(const OneFileVfs&) = delete;
};

using VectorMap = Eigen::Map<Eigen::VectorXd>;
using ConstVectorMap = Eigen::Map<const Eigen::VectorXd>;

}  // namespace

void MujocoSim::DataDeleter::operator()(mjData* data) const { mj_deleteData(data); }

void MujocoSim::install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_error = &raise_mujoco_error;
    mju_user_warning = &log_mujoco_warning;
  });
}

MujocoSim::MujocoSim(std::shared_ptr<const mjModel> model, std::string name)
    : model_(std::move(model)), name_(std::move(name)) {
  data_.reset(mj_makeData(model_.get()));
  require(data_ != nullptr, "MuJoCo could not allocate the simulation data", name_);
  mj_forward(model_.get(), data_.get());
}

MujocoSim MujocoSim::from_xml(std::string_view mjcf, std::string_view name) {
  install_handlers();
  std::array<char, kErrorSize> error{};
  mjModel* model = nullptr;
  {
    std::lock_guard<std::mutex> lock(load_mutex());
    OneFileVfs vfs("model.xml", mjcf);
    model = mj_loadXML("model.xml", vfs.vfs.get(), error.data(), kErrorSize);
  }
  if (model == nullptr)
    throw Error("MuJoCo rejected the model: " + std::string(error.data()), std::string(name));
  return MujocoSim(own(model), std::string(name));
}

MujocoSim MujocoSim::from_file(const std::filesystem::path& file) {
  install_handlers();
  const std::string where = file.string();
  require(std::filesystem::is_regular_file(file), "no such model file", where);
  std::array<char, kErrorSize> error{};
  mjModel* model = nullptr;
  {
    std::lock_guard<std::mutex> lock(load_mutex());
    model = mj_loadXML(where.c_str(), nullptr, error.data(), kErrorSize);
  }
  if (model == nullptr)
    throw Error("MuJoCo rejected the model: " + std::string(error.data()), where);
  return MujocoSim(own(model), where);
}

MujocoSim::MujocoSim(const MujocoSim& other) : model_(other.model_), name_(other.name_) {
  data_.reset(mj_copyData(nullptr, model_.get(), other.data_.get()));
  require(data_ != nullptr, "MuJoCo could not copy the simulation data", name_);
}

MujocoSim& MujocoSim::operator=(const MujocoSim& other) {
  if (this != &other) *this = MujocoSim(other);
  return *this;
}

int MujocoSim::id_of(int type, std::string_view element) const {
  const std::string text(element);
  const int id = mj_name2id(model_.get(), type, text.c_str());
  if (id < 0) {
    throw Error("the model has no " + std::string(mju_type2Str(type)) + " named '" + text + "'",
                name_);
  }
  return id;
}

void MujocoSim::reset() {
  mj_resetData(model_.get(), data_.get());
  mj_forward(model_.get(), data_.get());
}

void MujocoSim::save_state(SnapshotWriter& out) const {
  const mjModel* m = model_.get();
  const mjData* d = data_.get();
  out.section("MujocoSim");
  out.put(d->time);
  out.put_matrix(ConstVectorMap(d->qpos, m->nq));
  out.put_matrix(ConstVectorMap(d->qvel, m->nv));
  out.put_matrix(ConstVectorMap(d->act, m->na));
  out.put_matrix(ConstVectorMap(d->qacc_warmstart, m->nv));
  out.put_matrix(ConstVectorMap(d->ctrl, m->nu));
  out.put_matrix(ConstVectorMap(d->qfrc_applied, m->nv));
  out.put_matrix(ConstVectorMap(d->xfrc_applied, 6 * m->nbody));
}

void MujocoSim::load_state(SnapshotReader& in) {
  const mjModel* m = model_.get();
  mjData* d = data_.get();
  in.section("MujocoSim");
  const double time = in.get_double();
  Eigen::VectorXd qpos(m->nq), qvel(m->nv), act(m->na), warmstart(m->nv), ctrl(m->nu), qfrc(m->nv),
      xfrc(6 * m->nbody);
  for (Eigen::VectorXd* v : {&qpos, &qvel, &act, &warmstart, &ctrl, &qfrc, &xfrc}) {
    in.get_matrix(*v);
  }
  d->time = time;
  VectorMap(d->qpos, m->nq) = qpos;
  VectorMap(d->qvel, m->nv) = qvel;
  VectorMap(d->act, m->na) = act;
  VectorMap(d->qacc_warmstart, m->nv) = warmstart;
  VectorMap(d->ctrl, m->nu) = ctrl;
  VectorMap(d->qfrc_applied, m->nv) = qfrc;
  VectorMap(d->xfrc_applied, 6 * m->nbody) = xfrc;
  // Positions of bodies, geoms and sites for whoever reads them next; mj_step recomputes
  // everything it needs from the state above.
  mj_kinematics(m, d);
}

}  // namespace tendril::physics
