#include "tendril/safety/value_map.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/safety/safety_critic.hpp"
#include "tendril/safety/safety_evaluation.hpp"
#include "tendril/safety/search_space.hpp"

namespace tendril::safety {

double ValueMap::fraction_outside_analytic(double epsilon) const {
  if (!has_analytic_set) return std::numeric_limits<double>::quiet_NaN();
  int64_t learned = 0, outside = 0;
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    if (rows(i, 2) <= epsilon) continue;
    ++learned;
    if (rows(i, rows.cols() - 1) < 0.5) ++outside;
  }
  return learned == 0 ? std::numeric_limits<double>::quiet_NaN()
                      : static_cast<double>(outside) / static_cast<double>(learned);
}

void ValueMap::write_csv(const std::filesystem::path& file) const {
  std::ostringstream text;
  text.precision(9);
  for (std::size_t j = 0; j < columns.size(); ++j) text << (j ? "," : "") << columns[j];
  text << "\n";
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    for (Eigen::Index j = 0; j < rows.cols(); ++j) text << (j ? "," : "") << rows(i, j);
    text << "\n";
  }
  write_file_atomically(file, text.str(), file.string());
}

ValueMap value_map_of_run(const std::filesystem::path& run_directory,
                          const ValueMapOptions& options) {
  require(options.resolution >= 2 && options.extent > 0.0,
          "the map needs at least 2 points per axis and a positive extent", "value_map_of_run");
  const rl::Experiment run = task_experiment_of_run(run_directory);
  const auto critic = load_safety_critic(run_directory / "safety.critic");
  auto env = envs::make(run.env.id, run.env.params);
  const auto space = search_space_of(*env);
  const int n = space->dimension();
  require(options.x_axis != options.y_axis && options.x_axis >= 0 && options.y_axis >= 0 &&
              options.x_axis < n && options.y_axis < n,
          "the axes must be two different coordinates of the state", "value_map_of_run");
  Eigen::VectorXd state = options.fixed.size() == 0 ? Eigen::VectorXd::Zero(n) : options.fixed;
  require(state.size() == n, "one fixed value per state coordinate", "value_map_of_run");

  ValueMap map;
  const auto& names = space->names();
  map.columns = {names[static_cast<std::size_t>(options.x_axis)],
                 names[static_cast<std::size_t>(options.y_axis)], "value"};
  const int actions = env->action_space().size();
  for (int k = 0; k < actions; ++k) map.columns.push_back("action_" + std::to_string(k));
  map.has_analytic_set = space->analytically_safe(state).has_value();
  if (map.has_analytic_set) map.columns.push_back("analytic_safe");
  const int r = options.resolution;
  map.rows.resize(static_cast<Eigen::Index>(r) * r, static_cast<Eigen::Index>(map.columns.size()));
  const Eigen::VectorXd& scales = space->scales();
  for (int i = 0; i < r; ++i) {
    for (int j = 0; j < r; ++j) {
      state[options.x_axis] = options.extent * (-1.0 + 2.0 * i / (r - 1));
      state[options.y_axis] = options.extent * (-1.0 + 2.0 * j / (r - 1));
      const Observation x = space->observation(state);
      const Action action = critic->safe_action(x);
      auto row = map.rows.row(static_cast<Eigen::Index>(i) * r + j);
      row[0] = state[options.x_axis] * scales[options.x_axis];
      row[1] = state[options.y_axis] * scales[options.y_axis];
      row[2] = critic->value(x, action);
      for (int k = 0; k < actions; ++k) row[3 + k] = action[k];
      if (map.has_analytic_set) row[3 + actions] = *space->analytically_safe(state) ? 1.0 : 0.0;
    }
  }
  return map;
}

}  // namespace tendril::safety
