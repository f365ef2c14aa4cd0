#include "tendril/physics/rod/rod_pool.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <typeinfo>
#if __has_include(<cxxabi.h>)
#include <cxxabi.h>
#endif

#include "tendril/core/error.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/damping.hpp"

namespace tendril::physics {

namespace {

constexpr const char* kWho = "RodPool";

// The readable name of a part's type, for the error that names an unsupported one.
std::string type_name(const RodPart& part) {
  const char* mangled = typeid(part).name();
#if __has_include(<cxxabi.h>)
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> readable(
      abi::__cxa_demangle(mangled, nullptr, nullptr, &status), std::free);
  if (status == 0 && readable) return readable.get();
#endif
  return mangled;
}

std::string stage_names(uint32_t stages) {
  const std::pair<RodStage, const char*> names[] = {{kConstrainValues, "constrain values"},
                                                    {kStartStep, "start step"},
                                                    {kLoads, "loads"},
                                                    {kContact, "contact"},
                                                    {kConstrainRates, "constrain rates"},
                                                    {kDampRates, "damp rates"}};
  std::string text;
  for (const auto& [stage, name] : names) {
    if (stages & stage) text += (text.empty() ? "" : ", ") + std::string(name);
  }
  return text;
}

std::string shape(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + " × " + std::to_string(cols);
}

// Raises Error unless `state` holds a configuration of `model`'s size.
void check_sized(const RodModel& model, const RodState& state, const char* who) {
  const int n = model.n_elements;
  const auto check = [&](const char* name, Eigen::Index rows, Eigen::Index cols,
                         Eigen::Index want_rows, Eigen::Index want_cols) {
    if (rows != want_rows || cols != want_cols) {
      throw Error(std::string("state.") + name + " is " + shape(rows, cols) +
                      "; the pool's rods (" + std::to_string(n) + " elements) need " +
                      shape(want_rows, want_cols),
                  who);
    }
  };
  check("positions", state.positions.rows(), state.positions.cols(), 3, n + 1);
  check("velocities", state.velocities.rows(), state.velocities.cols(), 3, n + 1);
  check("directors", state.directors.rows(), state.directors.cols(), 9, n);
  check("angular_velocities", state.angular_velocities.rows(), state.angular_velocities.cols(), 3,
        n);
}

}  // namespace

RodPool::RodPool(const Rod& prototype, int count) : model_(prototype.model()), count_(count) {
  if (count < 1) throw Error("need at least one rod, got " + std::to_string(count), kWho);
  if (prototype.is_implicit()) {
    throw Error("the prototype rod steps implicitly; a RodPool advances by position Verlet only",
                kWho);
  }
  const auto& parts = prototype.parts();
  const SplineActuation* prototype_muscles = nullptr;
  for (std::size_t index = 0; index < parts.size(); ++index) {
    const RodPart& part = *parts[index];
    if (const auto* muscles = dynamic_cast<const SplineActuation*>(&part)) {
      if (prototype_muscles != nullptr) {
        throw Error("the prototype has a second SplineActuation (part " + std::to_string(index) +
                        "); a RodPool mirrors at most one",
                    kWho);
      }
      prototype_muscles = muscles;
      loads_.push_back({LoadKind::kMuscles});
    } else {
      mirror(part, static_cast<int>(index));
    }
  }

  const int blocks = (count + kRodLanes - 1) / kRodLanes;
  blocks_.resize(blocks);
  stopped_.resize(model_);
  for (RodLanes& lanes : blocks_) {
    lanes.resize(model_);
    // Lanes past the last rod carry the prototype too, so that they compute finite values.
    for (int l = 0; l < kRodLanes; ++l) lanes.set_lane(l, prototype.state());
  }
  finite_.assign(count, static_cast<char>(prototype.state_is_finite()));
  if (prototype_muscles != nullptr) {
    muscles_.assign(count, *prototype_muscles);
    muscles_rate_limited_ = std::isfinite(prototype_muscles->spec().max_change_per_step);
    const int n = model_.n_elements;
    for (RodLanes& lanes : blocks_) {
      for (int l = 0; l < kRodLanes; ++l) {
        for (int k = 0; k < 3; ++k) {
          for (int i = 0; i < n; ++i) {
            lanes.muscle_couples(l, k * n + i) = prototype_muscles->couples()(k, i);
          }
        }
      }
    }
  }
}

void RodPool::mirror(const RodPart& part, int index) {
  if (const auto* clamp = dynamic_cast<const FixedEnd*>(&part)) {
    clamps_.push_back({clamp->position(), clamp->directors()});
  } else if (const auto* damping = dynamic_cast<const InternalDamping*>(&part)) {
    Load load{LoadKind::kInternalDamping};
    load.coefficient = damping->coefficient();
    loads_.push_back(load);
  } else if (const auto* rates = dynamic_cast<const AnalyticalLinearDamping*>(&part)) {
    rate_dampings_.push_back({rates->velocity_factors(), rates->angular_factors()});
  } else if (const auto* gravity = dynamic_cast<const Gravity*>(&part)) {
    Load load{LoadKind::kGravity};
    load.first = gravity->acceleration();
    loads_.push_back(load);
  } else if (const auto* forces = dynamic_cast<const EndForces*>(&part)) {
    Load load{LoadKind::kEndForces};
    load.first = forces->start_force();
    load.second = forces->end_force();
    load.ramp_time = forces->ramp_time();
    loads_.push_back(load);
  } else {
    throw Error("part " + std::to_string(index) + " of the prototype, " + type_name(part) +
                    " (stages: " + stage_names(part.stages()) +
                    "), is not one a RodPool mirrors; it mirrors FixedEnd, InternalDamping, "
                    "AnalyticalLinearDamping, Gravity, EndForces and one SplineActuation",
                kWho);
  }
}

void RodPool::check_rod(int rod, const char* who) const {
  if (rod < 0 || rod >= count_) {
    throw Error("rod " + std::to_string(rod) + " outside [0, " + std::to_string(count_ - 1) + "]",
                who);
  }
}

bool RodPool::advance(int steps) {
  if (steps > 0) {
    for (int block = 0; block < static_cast<int>(blocks_.size()); ++block) {
      step_block(block, steps);
    }
  }
  return std::all_of(finite_.begin(), finite_.end(), [](char finite) { return finite != 0; });
}

// Rod::advance for the lanes of one block: position Verlet (Gazzola et al. 2018, §3.3) with the
// half kinematic steps between two steps of one call taken as one.
void RodPool::step_block(int block, int steps) {
  RodLanes& lanes = blocks_[block];
  const int first = block * kRodLanes;
  LaneMask live{};
  bool any_live = false, any_stopped = false;
  for (int l = 0; l < kRodLanes; ++l) {
    const int rod = first + l;
    live[l] = rod < count_ && finite_[rod];
    any_live = any_live || live[l];
    any_stopped = any_stopped || (rod < count_ && !finite_[rod]);
  }
  if (!any_live) return;
  // Stopped rods compute along with the others and get their values back afterwards.
  if (any_stopped) {
    stopped_.positions = lanes.positions;
    stopped_.velocities = lanes.velocities;
    stopped_.directors = lanes.directors;
    stopped_.angular_velocities = lanes.angular_velocities;
    stopped_.time = lanes.time;
  }

  const double dt = model_.time_step;
  lanes_kinematic_step(model_, lanes, 0.5 * dt, live);
  for (int s = 0; s < steps; ++s) {
    lanes.time.array() += 0.5 * dt;
    constrain_values(lanes);
    if (muscles_rate_limited_) {
      for (int l = 0; l < kRodLanes; ++l) {
        if (!live[l]) continue;
        muscles_[first + l].start_step(model_, scratch_, dt);
        scatter_couples(first + l);
      }
    }
    lanes_internal_loads(model_, lanes, live);
    lanes.external_forces.setZero();
    lanes.external_torques.setZero();
    add_loads(lanes);
    lanes_dynamic_step(model_, lanes, dt);
    constrain_and_damp_rates(lanes);
    const bool last = s + 1 == steps;
    lanes_kinematic_step(model_, lanes, last ? 0.5 * dt : dt, live);
    lanes.time.array() += 0.5 * dt;
  }
  constrain_values(lanes);

  const LaneMask finite = lanes.finite_lanes();
  for (int l = 0; l < kRodLanes; ++l) {
    const int rod = first + l;
    if (live[l]) {
      finite_[rod] = finite[l];
    } else if (rod < count_) {
      lanes.positions.row(l) = stopped_.positions.row(l);
      lanes.velocities.row(l) = stopped_.velocities.row(l);
      lanes.directors.row(l) = stopped_.directors.row(l);
      lanes.angular_velocities.row(l) = stopped_.angular_velocities.row(l);
      lanes.time.row(l) = stopped_.time.row(l);
    }
  }
}

void RodPool::constrain_values(RodLanes& lanes) const {
  const int n = model_.n_elements;
  for (const Clamp& clamp : clamps_) {
    for (int k = 0; k < 3; ++k) {
      lanes.positions.col(k * (n + 1)).setConstant(clamp.position[k]);
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        lanes.directors.col((3 * r + c) * n).setConstant(clamp.directors(r, c));
      }
    }
  }
}

void RodPool::add_loads(RodLanes& lanes) const {
  const int n = model_.n_elements;
  for (const Load& load : loads_) {
    switch (load.kind) {
      case LoadKind::kInternalDamping: {
        // InternalDamping::add_loads, lane by lane.
        const double nu = load.coefficient;
        for (int k = 0; k < 3; ++k) {
          const auto length = [&](int i) { return RodLanes::at(lanes.lengths, n, 0, i); };
          const auto v = [&](int j) { return RodLanes::at(lanes.velocities, n + 1, k, j); };
          {
            double* force = RodLanes::at(lanes.external_forces, n + 1, k, 0);
            const double *l0 = length(0), *v0 = v(0), *v1 = v(1);
#pragma omp simd
            for (int l = 0; l < kRodLanes; ++l) {
              force[l] -= 0.25 * nu * l0[l] * (v0[l] + v1[l]);
            }
          }
          for (int j = 1; j < n; ++j) {
            double* force = RodLanes::at(lanes.external_forces, n + 1, k, j);
            const double *la = length(j - 1), *lb = length(j);
            const double *va = v(j - 1), *vb = v(j), *vc = v(j + 1);
#pragma omp simd
            for (int l = 0; l < kRodLanes; ++l) {
              force[l] -= 0.25 * nu * (la[l] * (va[l] + vb[l]) + lb[l] * (vb[l] + vc[l]));
            }
          }
          {
            double* force = RodLanes::at(lanes.external_forces, n + 1, k, n);
            const double *la = length(n - 1), *va = v(n - 1), *vb = v(n);
#pragma omp simd
            for (int l = 0; l < kRodLanes; ++l) {
              force[l] -= 0.25 * nu * la[l] * (va[l] + vb[l]);
            }
          }
          for (int i = 0; i < n; ++i) {
            double* torque = RodLanes::at(lanes.external_torques, n, k, i);
            const double* li = length(i);
            const double* w = RodLanes::at(lanes.angular_velocities, n, k, i);
#pragma omp simd
            for (int l = 0; l < kRodLanes; ++l) torque[l] -= nu * li[l] * w[l];
          }
        }
        break;
      }
      case LoadKind::kMuscles:
        lanes.external_torques += lanes.muscle_couples;
        break;
      case LoadKind::kGravity:
        // Gravity::add_loads forms F + g m in one Eigen expression, which GCC with the build's
        // -ffp-contract=fast fuses into one multiply-add; here g m is the same for every lane
        // (hoisted out of the loop, so never fused), hence the explicit fma.
        for (int k = 0; k < 3; ++k) {
          for (int j = 0; j <= n; ++j) {
            double* force = RodLanes::at(lanes.external_forces, n + 1, k, j);
            const double g = load.first[k], mass = model_.node_masses[j];
#pragma omp simd
            for (int l = 0; l < kRodLanes; ++l) force[l] = std::fma(g, mass, force[l]);
          }
        }
        break;
      case LoadKind::kEndForces:
        for (int l = 0; l < kRodLanes; ++l) {
          const double factor =
              load.ramp_time > 0.0 ? std::min(lanes.time(l, 0) / load.ramp_time, 1.0) : 1.0;
          for (int k = 0; k < 3; ++k) {
            lanes.external_forces(l, k * (n + 1)) += factor * load.first[k];
            lanes.external_forces(l, k * (n + 1) + n) += factor * load.second[k];
          }
        }
        break;
    }
  }
}

void RodPool::constrain_and_damp_rates(RodLanes& lanes) const {
  const int n = model_.n_elements;
  for (std::size_t c = 0; c < clamps_.size(); ++c) {
    for (int k = 0; k < 3; ++k) {
      lanes.velocities.col(k * (n + 1)).setZero();
      lanes.angular_velocities.col(k * n).setZero();
    }
  }
  for (const RateDamping& damping : rate_dampings_) {
    for (int k = 0; k < 3; ++k) {
      for (int j = 0; j <= n; ++j) {
        lanes.velocities.col(k * (n + 1) + j) *= damping.velocity_factors[j];
      }
      for (int i = 0; i < n; ++i) {
        lanes.angular_velocities.col(k * n + i) *= damping.angular_factors(k, i);
      }
    }
  }
}

void RodPool::scatter_couples(int rod) {
  RodLanes& lanes = blocks_[rod / kRodLanes];
  const int lane = rod % kRodLanes, n = model_.n_elements;
  const Vectors& couples = muscles_[rod].couples();
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < n; ++i) lanes.muscle_couples(lane, k * n + i) = couples(k, i);
  }
}

bool RodPool::is_finite(int rod) const {
  check_rod(rod, "RodPool::is_finite");
  return finite_[rod] != 0;
}

void RodPool::set_state(int rod, const RodState& state) {
  check_rod(rod, "RodPool::set_state");
  check_sized(model_, state, "RodPool::set_state");
  RodLanes& lanes = blocks_[rod / kRodLanes];
  const int lane = rod % kRodLanes;
  lanes.set_lane(lane, state);
  finite_[rod] = lanes.finite_lanes()[lane];
}

void RodPool::get_state(int rod, RodState& state) const {
  check_rod(rod, "RodPool::get_state");
  check_sized(model_, state, "RodPool::get_state");
  blocks_[rod / kRodLanes].get_lane(rod % kRodLanes, state);
}

Eigen::Vector3d RodPool::node_position(int rod, int node) const {
  check_rod(rod, "RodPool::node_position");
  const int n = model_.n_elements;
  if (node < 0 || node > n) {
    throw Error("node " + std::to_string(node) + " outside [0, " + std::to_string(n) + "]",
                "RodPool::node_position");
  }
  const RodLanes& lanes = blocks_[rod / kRodLanes];
  const int lane = rod % kRodLanes;
  return {lanes.positions(lane, node), lanes.positions(lane, (n + 1) + node),
          lanes.positions(lane, 2 * (n + 1) + node)};
}

Eigen::Vector3d RodPool::tip_velocity(int rod) const {
  check_rod(rod, "RodPool::tip_velocity");
  const int n = model_.n_elements;
  const RodLanes& lanes = blocks_[rod / kRodLanes];
  const int lane = rod % kRodLanes;
  return {lanes.velocities(lane, n), lanes.velocities(lane, (n + 1) + n),
          lanes.velocities(lane, 2 * (n + 1) + n)};
}

double RodPool::time(int rod) const {
  check_rod(rod, "RodPool::time");
  return blocks_[rod / kRodLanes].time(rod % kRodLanes, 0);
}

void RodPool::set_targets(int rod, const Eigen::VectorXd& targets) {
  check_rod(rod, "RodPool::set_targets");
  if (muscles_.empty())
    throw Error("the prototype rod has no SplineActuation", "RodPool::set_targets");
  muscles_[rod].set_targets(targets);
  // Rate-limited muscles update their couples at the start of each step instead.
  if (!muscles_rate_limited_) scatter_couples(rod);
}

const SplineActuation& RodPool::muscles(int rod) const {
  check_rod(rod, "RodPool::muscles");
  if (muscles_.empty()) throw Error("the prototype rod has no SplineActuation", "RodPool::muscles");
  return muscles_[rod];
}

}  // namespace tendril::physics
