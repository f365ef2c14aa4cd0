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

namespace {

// Model 1 (kTip) or Model 3 (kTrajectory) of BeamObservation.
std::vector<EnvDescription::Entries> beam_observation(BeamObservation observation) {
  if (observation == BeamObservation::kTip) {
    return {{"tip x, y (centroid of the last row, lab frame)", "m", 2}, {"target x, y", "m", 2}};
  }
  return {{"centres of torque rows 1..5, x then y of each", "m", 10},
          {"tip x, y", "m", 2},
          {"tip velocity x, y", "m/s", 2},
          {"target x, y", "m", 2},
          {"target velocity x, y", "m/s", 2}};
}

std::vector<EnvDescription::Parameter> common_parameters() {
  return {
      {"torque_scale", "N·m", "torque per unit action"},
      {"control_period", "s", "one step"},
      {"observation", "",
       "tip (Model 1, 4), six_points (Model 2, 14) or trajectory (Model 3, "
       "18); the task's by default",
       true},
      {"distance_weight", "1/m", "w_d"},
      {"velocity_weight", "s/m", "w_v"},
      {"energy_weight", "1", "w_E"},
      {"energy_units", "", "r_E with τ in newton_metres (default) or normalised", true},
      {"max_distance", "m", "tip–target distance that ends the episode; 0: never"},
      {"success_distance", "m", "distance that counts as success"},
      {"nan_penalty", "1", "reward of a step whose state became non-finite"},
      {"integrator", "", "the lattice's: bdf2 (default), backward_euler or symplectic_euler", true},
      {"time_step", "s", "lattice time step"},
      {"newton_iterations", "", "per implicit step"},
      {"mass_damping", "1/s", "Rayleigh α"},
      {"stiffness_damping", "s", "Rayleigh β"}};
}

EnvDescription beam_description(BeamObservation observation, std::string reward,
                                std::vector<EnvDescription::Parameter> path) {
  std::vector<EnvDescription::Parameter> parameters = common_parameters();
  parameters.insert(parameters.end(), path.begin(), path.end());
  return {
      .observation = beam_observation(observation),
      .action = {{"torques of rows 1..5, in [−1, 1] × torque_scale", "1", 5}},
      .reward = std::move(reward),
      .episode_end =
          "terminated on a non-finite state or beyond max_distance (when set); "
          "truncated by the time limit",
      .parameters = std::move(parameters),
  };
}

// `angular_velocity`: the task's default range, as text.
std::vector<EnvDescription::Parameter> arc_parameters(const std::string& angular_velocity) {
  return {{"arc_angle", "°", "angle of each arc"},
          {"mean_reversal_interval", "s", "mean time between reversals of direction"},
          {"radius", "m", "[low, high] of the arcs' radius; default [0.2, 0.6]", true},
          {"angular_velocity", "rad/s",
           "[low, high] of the target's angular velocity; default " + angular_velocity, true},
          {"levels", "", "[{radius, angular_velocity}, ...]: curriculum levels", true}};
}

}  // namespace

EnvDescription arc_follow_description() {
  return beam_description(BeamObservation::kTip,
                          "−20 r_d, r_d = ‖tip − target‖ (seed 003 §IV, Model 1)",
                          arc_parameters("[0.5, 0.5]"));
}

EnvDescription trajectory_follow_description() {
  return beam_description(BeamObservation::kTrajectory,
                          "−40 r_d − 10 r_v, r_v = ‖v_tip − v_target‖ (seed 003 §V, case 2)",
                          arc_parameters("[0.1, 0.5]"));
}

EnvDescription energy_aware_follow_description() {
  return beam_description(BeamObservation::kTrajectory,
                          "−40 r_d − 10 r_v − r_E, r_E = |Σ τ_i θ_i| the rows' torque work "
                          "(seed 003 §VI)",
                          arc_parameters("[0.1, 0.5]"));
}

EnvDescription ellipse_follow_description() {
  return beam_description(
      BeamObservation::kTrajectory, "−40 r_d − 10 r_v (seed 003 §VII)",
      {{"top", "m", "height of the ellipse's top"},
       {"semi_major_axis", "m", "[low, high] of the last level; default [0.18, 0.25]", true},
       {"eccentricity", "1", "[low, high] of the last level; default [0.5, 0.8]", true},
       {"angular_velocity", "rad/s", "[low, high] of the last level; default [0.5, 1.0]", true},
       {"levels", "", "[{semi_major_axis, eccentricity, angular_velocity}, ...]", true}});
}

}  // namespace tendril::envs::beam
