// `tendril simulate`: a Cosserat-rod arm under a constant spline muscle couple.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"

namespace tendril::apps {

namespace {

namespace fs = std::filesystem;
using physics::ElasticaArm;
using physics::ElasticaArmSpec;

ElasticaArmSpec arm_spec_from(const Config& arm) {
  const std::string name = arm.get_or<std::string>("case", "tracking");
  ElasticaArmSpec spec;
  if (name == "tracking") {
    spec = ElasticaArmSpec::tracking();
  } else if (name == "structured_obstacles") {
    spec = ElasticaArmSpec::structured_obstacles();
  } else {
    throw Error("unknown arm case '" + name + "' (expected tracking or structured_obstacles)",
                arm.source() + ": " + arm.path() + ".case");
  }
  spec.n_elements = arm.get_or<int>("n_elements", spec.n_elements);
  spec.time_step = arm.get_or<double>("time_step", spec.time_step);
  spec.damping = arm.get_or<double>("damping", spec.damping);
  return spec;
}

// Control-point values per direction; the directions listed are the active ones.
Eigen::VectorXd actuation_from(const Config& actuation, physics::SplineActuationSpec& spec) {
  const char* names[3] = {"normal", "binormal", "twist"};
  std::vector<double> targets;
  int count = -1;
  for (int m = 0; m < 3; ++m) {
    spec.directions[m] = actuation.has(names[m]);
    if (!spec.directions[m]) continue;
    const std::vector<double> values = actuation.get<std::vector<double>>(names[m]);
    const std::string where = actuation.source() + ": " + actuation.path() + "." + names[m];
    require(count < 0 || static_cast<int>(values.size()) == count,
            "every direction needs the same number of control points", where);
    for (double v : values)
      require(v >= -1.0 && v <= 1.0, "control points must lie in [-1, 1]", where);
    count = static_cast<int>(values.size());
    targets.insert(targets.end(), values.begin(), values.end());
  }
  require(count > 0, "list control points for at least one of normal, binormal, twist",
          actuation.source() + ": " + actuation.path());
  spec.control_points = count;
  spec.max_torque = actuation.get_or<double>("max_torque", spec.max_torque);
  return Eigen::Map<Eigen::VectorXd>(targets.data(), static_cast<Eigen::Index>(targets.size()));
}

fs::path output_directory(const Arguments& line, const std::string& configured) {
  fs::path directory = line.value("output", "");
  if (directory.empty()) {
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    directory = configured + "-" + stamp;
  }
  if (fs::exists(directory) && !fs::is_empty(directory) && !line.has("overwrite")) {
    throw Error("output directory is not empty; pass --overwrite to replace its files",
                directory.string());
  }
  fs::create_directories(directory);
  return directory;
}

}  // namespace

int simulate_command(const Arguments& line) {
  const Config config = line.load_config(file_kind::kSimulation);
  ElasticaArmSpec spec = arm_spec_from(config.child("arm"));
  const Eigen::VectorXd targets = actuation_from(config.child("actuation"), spec.actuation);
  const double duration = config.get<double>("duration");
  const double record_interval = config.get_or<double>("record_interval", 0.01);
  const std::string configured_output = config.get_or<std::string>("output", "runs/simulate");
  require(duration > 0.0, "duration must be positive", config.source() + ": duration");
  require(record_interval > 0.0, "record_interval must be positive",
          config.source() + ": record_interval");
  config.reject_unknown();

  ElasticaArm arm = physics::build_elastica_arm(spec);
  arm.muscles->set_targets(targets);
  const fs::path directory = output_directory(line, configured_output);
  // The files are written whole at the end, each checked (a full disk is an error naming it).
  std::ostringstream tip_file;
  tip_file.precision(6);
  tip_file << "time,tip_x,tip_y,tip_z,tip_speed,kinetic_energy,shear_stretch_energy,"
              "bend_twist_energy,contacts\n";
  const int steps_per_record =
      std::max(1, static_cast<int>(std::lround(record_interval / spec.time_step)));
  const int records = static_cast<int>(std::ceil(duration / (steps_per_record * spec.time_step)));
  std::printf(
      "tendril simulate: %d-element Elastica arm, dt %.2g s, %.3g s simulated, %zu active "
      "muscle directions\n",
      spec.n_elements, spec.time_step, duration,
      static_cast<size_t>(spec.actuation.active_directions()));
  std::printf("%9s %10s %10s %10s %11s %12s\n", "time [s]", "tip x [m]", "tip y [m]", "tip z [m]",
              "speed [m/s]", "energy [J]");

  double stepping_seconds = 0.0;
  int64_t steps = 0;
  auto record = [&](bool print) {
    const physics::RodEnergies energy = arm.rod.energies();
    const Eigen::Vector3d tip = arm.rod.tip_position();
    const double speed = arm.rod.tip_velocity().norm();
    tip_file << arm.rod.time() << ',' << tip.x() << ',' << tip.y() << ',' << tip.z() << ',' << speed
             << ',' << energy.translational_kinetic + energy.rotational_kinetic << ','
             << energy.shear_stretch << ',' << energy.bend_twist << ','
             << (arm.contact ? arm.contact->contacts() : 0) << '\n';
    if (print) {
      std::printf("%9.3f %10.4f %10.4f %10.4f %11.4f %12.5f\n", arm.rod.time(), tip.x(), tip.y(),
                  tip.z(), speed, energy.total());
    }
  };
  record(true);
  for (int r = 1; r <= records; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const bool finite = arm.rod.advance(steps_per_record);
    stepping_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    steps += steps_per_record;
    if (!finite) {
      std::printf("the rod's state became non-finite at t = %.4f s; stopping\n", arm.rod.time());
      write_file_atomically(directory / "config.yaml", config.dump(), "config.yaml");
      write_file_atomically(directory / "tip.csv", tip_file.str(), "tip.csv");
      return 1;
    }
    record(r % std::max(1, records / 10) == 0 || r == records);
  }

  std::ostringstream node_file;
  node_file << "node,x,y,z\n";
  for (int j = 0; j <= arm.rod.n_elements(); ++j) {
    const Eigen::Vector3d x = arm.rod.state().positions.col(j);
    node_file << j << ',' << x.x() << ',' << x.y() << ',' << x.z() << '\n';
  }
  write_file_atomically(directory / "config.yaml", config.dump(), "config.yaml");
  write_file_atomically(directory / "tip.csv", tip_file.str(), "tip.csv");
  write_file_atomically(directory / "nodes.csv", node_file.str(), "nodes.csv");
  const double us_per_step = 1e6 * stepping_seconds / static_cast<double>(steps);
  std::printf("%lld steps in %.3f s of stepping: %.2f us per step (%.0f steps/s)\n",
              static_cast<long long>(steps), stepping_seconds, us_per_step, 1e6 / us_per_step);
  std::printf("wrote %s/tip.csv, nodes.csv and config.yaml\n", directory.string().c_str());
  return 0;
}

}  // namespace tendril::apps
