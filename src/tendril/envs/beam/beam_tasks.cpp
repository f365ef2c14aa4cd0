#include "tendril/envs/beam/beam_tasks.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/beam/arc_path.hpp"
#include "tendril/envs/beam/beam_env.hpp"
#include "tendril/envs/beam/ellipse_path.hpp"

namespace tendril::envs::beam {

namespace {

std::string key_of(const Config& config, const std::string& key) {
  return config.source() + ": " + (config.path().empty() ? key : config.path() + "." + key);
}

Range read_range(const Config& config, const std::string& key, const Range& fallback) {
  if (!config.has(key)) return fallback;
  const std::vector<double> values = config.get<std::vector<double>>(key);
  require(values.size() == 2 && values[0] <= values[1],
          "expected [low, high] with low <= high (equal values fix it)", key_of(config, key));
  return Range{values[0], values[1]};
}

template <typename Choice>
Choice read_choice(const Config& config, const std::string& key, Choice fallback,
                   const std::vector<std::pair<std::string, Choice>>& choices) {
  if (!config.has(key)) return fallback;
  const std::string name = config.get<std::string>(key);
  std::string known;
  for (const auto& [text, value] : choices) {
    if (text == name) return value;
    known += (known.empty() ? "" : ", ") + text;
  }
  throw Error("unknown value '" + name + "', expected one of " + known, key_of(config, key));
}

// The parameters every beam task shares, over the task's defaults in `spec`.
void read_common(const Config& params, BeamTaskSpec& spec) {
  spec.torque_scale = params.get_or<double>("torque_scale", spec.torque_scale);
  spec.control_period = params.get_or<double>("control_period", spec.control_period);
  spec.observation = read_choice<BeamObservation>(params, "observation", spec.observation,
                                                  {{"tip", BeamObservation::kTip},
                                                   {"six_points", BeamObservation::kSixPoints},
                                                   {"trajectory", BeamObservation::kTrajectory}});
  spec.weights.distance = params.get_or<double>("distance_weight", spec.weights.distance);
  spec.weights.velocity = params.get_or<double>("velocity_weight", spec.weights.velocity);
  spec.weights.energy = params.get_or<double>("energy_weight", spec.weights.energy);
  spec.energy_in_newton_metres =
      read_choice<bool>(params, "energy_units", spec.energy_in_newton_metres,
                        {{"newton_metres", true}, {"normalised", false}});
  spec.max_distance = params.get_or<double>("max_distance", spec.max_distance);
  spec.success_distance = params.get_or<double>("success_distance", spec.success_distance);
  spec.nan_penalty = params.get_or<double>("nan_penalty", spec.nan_penalty);

  physics::BeamLatticeSpec& lattice = spec.lattice;
  lattice.numerics.integrator = read_choice<physics::LatticeIntegrator>(
      params, "integrator", lattice.numerics.integrator,
      {{"bdf2", physics::LatticeIntegrator::kBdf2},
       {"backward_euler", physics::LatticeIntegrator::kBackwardEuler},
       {"symplectic_euler", physics::LatticeIntegrator::kSymplecticEuler}});
  lattice.numerics.time_step = params.get_or<double>("time_step", lattice.numerics.time_step);
  lattice.numerics.newton_iterations =
      params.get_or<int>("newton_iterations", lattice.numerics.newton_iterations);
  lattice.mass_damping = params.get_or<double>("mass_damping", kTaskMassDamping);
  lattice.stiffness_damping = params.get_or<double>("stiffness_damping", lattice.stiffness_damping);
  try {
    lattice.validate();
    spec.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), params.source() + ": " + params.path() + " (" + e.where() + ")");
  }
}

ArcSpec read_arc(const Config& params, const ArcLevel& defaults) {
  ArcSpec arc;
  arc.arc_angle = params.get_or<double>("arc_angle", arc.arc_angle);
  arc.mean_reversal_interval =
      params.get_or<double>("mean_reversal_interval", arc.mean_reversal_interval);
  const auto read_level = [](const Config& config, const ArcLevel& fallback) {
    return ArcLevel{read_range(config, "radius", fallback.radius),
                    read_range(config, "angular_velocity", fallback.angular_velocity)};
  };
  const ArcLevel last = read_level(params, defaults);
  if (params.has("levels")) {
    arc.levels.clear();
    for (const Config& level : params.children("levels")) {
      arc.levels.push_back(read_level(level, last));
      level.reject_unknown();
    }
  } else {
    arc.levels.assign(1, last);
  }
  try {
    arc.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), params.source() + ": " + params.path() + " (" + e.where() + ")");
  }
  return arc;
}

std::unique_ptr<Env> make_arc_task(const Config& params, BeamTaskSpec spec,
                                   const ArcLevel& defaults) {
  read_common(params, spec);
  return std::make_unique<BeamEnv>(spec, std::make_unique<ArcPath>(read_arc(params, defaults)));
}

}  // namespace

std::unique_ptr<Env> make_arc_follow(const Config& params) {
  BeamTaskSpec spec;
  spec.id = "Beam/ArcFollow-v0";
  spec.observation = BeamObservation::kTip;
  spec.weights = {-20.0, 0.0, 0.0};
  return make_arc_task(params, spec, ArcLevel{{0.2, 0.6}, {0.5, 0.5}});
}

std::unique_ptr<Env> make_trajectory_follow(const Config& params) {
  BeamTaskSpec spec;
  spec.id = "Beam/TrajectoryFollow-v0";
  spec.observation = BeamObservation::kTrajectory;
  spec.weights = {-40.0, -10.0, 0.0};
  return make_arc_task(params, spec, ArcLevel{{0.2, 0.6}, {0.1, 0.5}});
}

std::unique_ptr<Env> make_energy_aware_follow(const Config& params) {
  BeamTaskSpec spec;
  spec.id = "Beam/EnergyAwareFollow-v0";
  spec.observation = BeamObservation::kTrajectory;
  spec.weights = {-40.0, -10.0, -1.0};
  return make_arc_task(params, spec, ArcLevel{{0.2, 0.6}, {0.1, 0.5}});
}

std::unique_ptr<Env> make_ellipse_follow(const Config& params) {
  BeamTaskSpec spec;
  spec.id = "Beam/EllipseFollow-v0";
  spec.observation = BeamObservation::kTrajectory;
  spec.weights = {-40.0, -10.0, 0.0};
  spec.torque_scale = 8.0;
  read_common(params, spec);

  EllipseSpec ellipse;
  ellipse.top = params.get_or<double>("top", ellipse.top);
  const auto read_level = [](const Config& config, const EllipseLevel& fallback) {
    return EllipseLevel{read_range(config, "semi_major_axis", fallback.semi_major_axis),
                        read_range(config, "eccentricity", fallback.eccentricity),
                        read_range(config, "angular_velocity", fallback.angular_velocity)};
  };
  const EllipseLevel full = read_level(params, EllipseLevel{});
  if (params.has("levels")) {
    ellipse.levels.clear();
    for (const Config& level : params.children("levels")) {
      ellipse.levels.push_back(read_level(level, full));
      level.reject_unknown();
    }
  } else {
    ellipse.levels = EllipseSpec::default_levels(full);
  }
  try {
    ellipse.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), params.source() + ": " + params.path() + " (" + e.where() + ")");
  }
  return std::make_unique<BeamEnv>(spec, std::make_unique<EllipsePath>(ellipse));
}

}  // namespace tendril::envs::beam
