// `tendril safety`: train a task agent with a co-trained safety agent or a constrained baseline,
// evaluate runs with and without the safety filter, search ε₂ (Algorithm 3) and map the learned
// safety value (seed 001 ch. 6).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "limb_deployment.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/run_record.hpp"
#include "tendril/safety/constrained_experiment.hpp"
#include "tendril/safety/diamond_deployment.hpp"
#include "tendril/safety/run_epsilon_search.hpp"
#include "tendril/safety/safety_evaluation.hpp"
#include "tendril/safety/safety_experiment.hpp"
#include "tendril/safety/value_map.hpp"

namespace tendril::apps {
namespace {

void print_evaluation(const char* name, const safety::SafetyEvaluation& e) {
  std::printf("%-10s return %9.3f +/- %8.3f   safety rate %.3f   interventions %.3f\n", name,
              e.mean_return, e.std_return, e.safety_rate, e.intervention_rate);
}

// Rows [episode, t, x..., u..., unsafe] as CSV; the observation's and action's entries, whose
// sizes the rows do not carry, are named v0, v1, ...
void write_trajectory(const std::string& file, const std::vector<std::vector<double>>& steps) {
  std::ostringstream text;
  text << "episode,t";
  const std::size_t width = steps.empty() ? 3 : steps.front().size();
  for (std::size_t k = 2; k + 1 < width; ++k) text << ",v" << (k - 2);
  text << ",unsafe\n";
  for (const auto& row : steps) {
    for (std::size_t k = 0; k < row.size(); ++k) text << (k ? "," : "") << row[k];
    text << "\n";
  }
  write_file_atomically(file, text.str(), "--trajectory");
}

int evaluate(const std::filesystem::path& run, const std::vector<double>& epsilons, int episodes,
             uint64_t seed, const safety::TaskSource& task, const std::string& csv,
             const std::string& trajectory_csv = "") {
  std::ostringstream rows;
  rows << "epsilon,unfiltered_return,unfiltered_return_std,unfiltered_safety_rate,"
          "filtered_return,filtered_return_std,filtered_safety_rate,intervention_rate\n";
  for (double epsilon : epsilons) {
    std::vector<std::vector<double>> steps;
    const bool record = !trajectory_csv.empty() && epsilon == epsilons.front();
    const safety::RunSafetyEvaluation result =
        safety::evaluate_safety_run(run, epsilon, episodes, seed, task, record ? &steps : nullptr);
    if (record) write_trajectory(trajectory_csv, steps);
    std::printf("%d episodes (reset seeds %llu, ...), epsilon_2 = %g\n", episodes,
                static_cast<unsigned long long>(seed), epsilon);
    print_evaluation("task", result.unfiltered);
    if (result.filtered) print_evaluation("filtered", *result.filtered);
    const auto& u = result.unfiltered;
    rows << epsilon << "," << u.mean_return << "," << u.std_return << "," << u.safety_rate;
    if (result.filtered) {
      const auto& f = *result.filtered;
      rows << "," << f.mean_return << "," << f.std_return << "," << f.safety_rate << ","
           << f.intervention_rate << "\n";
    } else {
      rows << ",,,,\n";
    }
  }
  if (!csv.empty()) write_file_atomically(csv, rows.str(), csv);
  return 0;
}

}  // namespace

int safety_train(const Arguments& line, const Config& config, const rl::TrainOptions& options) {
  const std::optional<std::filesystem::path> output =
      line.has("output") ? std::optional<std::filesystem::path>(line.value("output", ""))
                         : std::nullopt;
  return run_safety_training(config, output, options, /*resuming=*/false);
}

int run_safety_training(const Config& config, const std::optional<std::filesystem::path>& output,
                        rl::TrainOptions options, bool resuming) {
  // The companion that trains beside the task agent, and how the finished run is judged: a
  // co-trained safety agent's own evaluation settings, the baselines unfiltered on 100 episodes.
  std::optional<safety::SafetyExperiment> co_trained;
  std::optional<safety::ConstrainedExperiment> baseline;
  std::string with;
  double epsilon = 0.0;
  int episodes = 100;
  if (config.has("safety")) {
    co_trained.emplace(safety::SafetyExperiment::from_config(config));
    options.companion = safety::co_trained_safety_agent(*co_trained);
    with = "a " + co_trained->safety_algorithm + " safety agent";
    epsilon = co_trained->eval_epsilon;
    episodes = co_trained->eval_episodes;
  } else {
    baseline.emplace(safety::ConstrainedExperiment::from_config(config));
    options.companion = safety::constrained_baseline(*baseline);
    with = "the " + baseline->method + " baseline";
  }
  const rl::Experiment& task = co_trained ? co_trained->task : baseline->task;
  const std::filesystem::path run = output.value_or(rl::default_run_directory(task));
  std::printf("%s %s with %s on %s for %lld steps, seed %llu -> %s\n",
              resuming ? "resuming" : "training", task.algorithm.c_str(), with.c_str(),
              task.env.id.c_str(), static_cast<long long>(task.n_timesteps),
              static_cast<unsigned long long>(task.seed), run.string().c_str());
  std::fflush(stdout);  // before the progress line on standard error
  catch_interrupts();
  const rl::TrainResult result =
      resuming ? rl::resume(run, task, options) : rl::train(task, run, options);
  const int status = report_training(result);
  if (!result.finished) return status;
  for (const auto& [name, value] : result.companion_scalars) {
    std::printf("%-32s %.6g\n", name.c_str(), value);
  }
  if (co_trained) {
    std::printf("safety critic:  %s/safety.critic\n", run.string().c_str());
  }
  return evaluate(run, {epsilon}, episodes, task.seed, {}, "");
}

int safety_eval_command(const Arguments& line) {
  const std::filesystem::path run = line.positional[0];
  // A co-training run brings its evaluation settings; any other run is judged unfiltered.
  int default_episodes = 100;
  double default_epsilon = 0.0;
  const uint64_t default_seed = safety::task_experiment_of_run(run).seed;
  const Config config = load_run_config(run);
  if (config.has("safety")) {
    const safety::SafetyExperiment experiment = safety::SafetyExperiment::from_config(config);
    default_episodes = experiment.eval_episodes;
    default_epsilon = experiment.eval_epsilon;
  }
  const int episodes = static_cast<int>(
      line.integer("episodes", default_episodes, 1, std::numeric_limits<int>::max()));
  const std::vector<double> epsilons = line.has("epsilon") ? line.numbers("epsilon", -1e300, 1e300)
                                                           : std::vector<double>{default_epsilon};
  safety::TaskSource task;
  if (line.has("task")) {
    const std::string value = line.value("task", "");
    task.kind =
        value == "random" ? safety::TaskSource::Kind::kRandom : safety::TaskSource::Kind::kRun;
    task.run = value;
  }
  return evaluate(run, epsilons, episodes, line.unsigned_integer("seed", default_seed), task,
                  line.value("csv", ""), line.value("trajectory", ""));
}

int safety_search_command(const Arguments& line) {
  const std::filesystem::path run = line.positional[0];
  safety::EpsilonSearchOptions options;
  options.unit_gradient = true;
  options.survivor_value = !line.has("final-value");
  options.restarts = static_cast<int>(line.integer("restarts", options.restarts, 1, 100000));
  options.step_size = line.number("step-size", options.step_size, 1e-12, 1e12);
  options.tolerance = line.number("tolerance", options.tolerance, 0.0, 1e12);
  const uint64_t seed = line.unsigned_integer("seed", 0);
  const safety::RunEpsilonSearch search = safety::search_epsilon_of_run(run, options, seed);
  std::ostringstream rows;
  rows << "restart,epsilon,iterations,converged";
  for (const std::string& name : search.state_names) rows << ",start_" << name;
  for (const std::string& name : search.state_names) rows << ",final_" << name;
  rows << "\n";
  for (std::size_t k = 0; k < search.result.runs.size(); ++k) {
    const safety::EpsilonSearchRun& r = search.result.runs[k];
    std::printf("restart %2zu: epsilon_2 %10.4f after %3zu iterations%s\n", k, r.epsilon,
                r.trace.size(), r.converged ? "" : " (not converged)");
    rows << k << "," << r.epsilon << "," << r.trace.size() << "," << (r.converged ? 1 : 0);
    const Eigen::VectorXd start = r.trace.empty() ? Eigen::VectorXd() : r.trace.front().state;
    const Eigen::VectorXd last = r.trace.empty() ? Eigen::VectorXd() : r.trace.back().state;
    for (Eigen::Index i = 0; i < search.state_scales.size(); ++i) {
      rows << "," << (start.size() ? start[i] * search.state_scales[i] : NAN);
    }
    for (Eigen::Index i = 0; i < search.state_scales.size(); ++i) {
      rows << "," << (last.size() ? last[i] * search.state_scales[i] : NAN);
    }
    rows << "\n";
  }
  std::printf("epsilon_2 = %.4f (the largest of %zu restarts, Algorithm 3)\n",
              search.result.epsilon, search.result.runs.size());
  const std::string csv = line.value("csv", "");
  if (!csv.empty()) write_file_atomically(csv, rows.str(), csv);
  return 0;
}

int safety_map_command(const Arguments& line) {
  require(line.has("output"), "needs -o FILE.csv, where the map is written", "safety map");
  safety::ValueMapOptions options;
  options.resolution = static_cast<int>(line.integer("resolution", options.resolution, 2, 2001));
  options.extent = line.number("extent", options.extent, 1e-12, 1e12);
  if (line.has("axes")) {
    const std::vector<double> axes = line.numbers("axes", 0, 1000);
    require(axes.size() == 2, "expected two coordinate indices I,J", "--axes");
    options.x_axis = static_cast<int>(axes[0]);
    options.y_axis = static_cast<int>(axes[1]);
  }
  if (line.has("fixed")) {
    const std::vector<double> fixed = line.numbers("fixed", -1e300, 1e300);
    options.fixed =
        Eigen::Map<const Eigen::VectorXd>(fixed.data(), static_cast<Eigen::Index>(fixed.size()));
  }
  const safety::ValueMap map = safety::value_map_of_run(line.positional[0], options);
  map.write_csv(line.value("output", ""));
  std::printf("%lld points -> %s\n", static_cast<long long>(map.rows.rows()),
              line.value("output", "").c_str());
  if (map.has_analytic_set && line.has("epsilon")) {
    for (double epsilon : line.numbers("epsilon", -1e300, 1e300)) {
      std::printf("epsilon_2 %g: %.4f of the learned safe states lie outside the analytic set\n",
                  epsilon, map.fraction_outside_analytic(epsilon));
    }
  }
  return 0;
}

int safety_diamond_command(const Arguments& line) {
  safety::DiamondOptions options;
  if (line.has("epsilon")) options.epsilons = line.numbers("epsilon", -1e300, 1e300);
  options.trials = static_cast<int>(line.integer("trials", options.trials, 1, 1000));
  options.seed = line.unsigned_integer("seed", 0);
  // The critic was learned in a model of the calibrated limb: deploy it on that calibration.
  const Config trained_env_params = safety::task_experiment_of_run(line.positional[0]).env.params;
  const LimbDeployment deployment = limb_deployment(line, &trained_env_params, "safety diamond");
  options.limb_params = deployment.params;
  std::printf("the limb's calibration: %s\n", deployment.calibration.c_str());
  const std::vector<safety::DiamondTrial> trials = safety::run_diamond(line.positional[0], options);
  std::ostringstream summary, paths;
  summary << "epsilon,trial,time_to_violation_s,intervention_rate\n";
  paths << "epsilon,trial,time_s,theta_x,theta_y,value,intervened,u_x,u_y\n";
  for (const safety::DiamondTrial& t : trials) {
    std::printf(
        "epsilon_2 %6g trial %d: %s, interventions %.3f\n", t.epsilon, t.trial,
        std::isnan(t.time_to_violation_s)
            ? "no violation in the sequence"
            : ("first violation at " + std::to_string(t.time_to_violation_s) + " s").c_str(),
        t.intervention_rate);
    summary << t.epsilon << "," << t.trial << "," << t.time_to_violation_s << ","
            << t.intervention_rate << "\n";
    for (Eigen::Index i = 0; i < t.trajectory.rows(); ++i) {
      paths << t.epsilon << "," << t.trial;
      for (Eigen::Index j = 0; j < t.trajectory.cols(); ++j) paths << "," << t.trajectory(i, j);
      paths << "\n";
    }
  }
  if (line.has("csv")) write_file_atomically(line.value("csv", ""), summary.str(), "--csv");
  if (line.has("trajectories")) {
    write_file_atomically(line.value("trajectories", ""), paths.str(), "--trajectories");
  }
  return 0;
}

}  // namespace tendril::apps
