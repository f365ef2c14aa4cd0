// `tendril adapt`: online adaptation of a trained policy on the pneumatic arm (seed 002 §V-C,
// V-D): BOAC or GPRCA in every goal × damage scenario × seed of an experiment file, with
// per-trial logs and a summary (Table II's parameters P1–P5).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/adapt/adapt_config.hpp"
#include "tendril/adapt/boac.hpp"
#include "tendril/adapt/gprca_trials.hpp"
#include "tendril/adapt/task_reaching_robot.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/run_lock.hpp"
#include "tendril/core/run_record.hpp"
#include "tendril/envs/pneumatic/reach_env.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::apps {

namespace fs = std::filesystem;

namespace {

// A mapping's YAML with every line indented, to nest it under a key.
std::string indented(const std::string& yaml) {
  std::istringstream lines(yaml);
  std::string line, out;
  while (std::getline(lines, line)) out += "  " + line + "\n";
  return out;
}

// The mappings' keys side by side (the caller keeps them disjoint), plus nested ones.
Config assembled(const std::vector<const Config*>& tops,
                 const std::vector<std::pair<std::string, const Config*>>& nested,
                 const std::string& source) {
  std::string yaml;
  for (const Config* top : tops) {
    if (!top->keys().empty()) yaml += top->dump() + "\n";
  }
  for (const auto& [key, config] : nested) {
    if (!config->keys().empty()) yaml += key + ":\n" + indented(config->dump());
  }
  return Config::parse(yaml.empty() ? "{}" : yaml, source);
}

std::unique_ptr<rl::Policy> load_trained_policy(const std::string& path) {
  const fs::path file = fs::is_directory(path) ? fs::path(path) / "model.policy" : fs::path(path);
  return rl::load_policy(file);
}

// Table II's parameters of one run (seed 002): P1 trials until the goal flag (or all trials),
// P2 mean steps per trial, P3 the goal flag, P4 collisions, P5 the last trial's final distance;
// plus the online time the trials took on the robot (steps × control period) and the learner's
// per-step update times.
struct RunSummary {
  std::string method, goal, scenario;
  uint64_t seed = 0;
  int trials = 0, oracle_trials = 0;
  double steps_per_trial = 0.0;
  bool goal_flag = false;
  int collisions = 0;
  double final_distance = 0.0;
  double robot_seconds = 0.0, oracle_robot_seconds = 0.0, wall_seconds = 0.0;
  double max_update_ms = 0.0, median_update_ms = 0.0, max_search_s = 0.0;
};

RunSummary summarize(const adapt::AdaptationResult& result, double period) {
  RunSummary summary;
  summary.goal_flag = result.goal_flag;
  int steps = 0;
  std::vector<double> medians;
  for (const adapt::AdaptationTrial& trial : result.trials) {
    if (trial.phase == "oracle") {
      ++summary.oracle_trials;
      summary.oracle_robot_seconds += period * trial.steps;
      continue;
    }
    if (summary.trials >= result.trials_to_goal) continue;  // after the goal flag
    ++summary.trials;
    steps += trial.steps;
    summary.collisions += trial.collision;
    summary.final_distance = trial.final_goal_distance;
    summary.max_update_ms = std::max(summary.max_update_ms, trial.max_update_ms);
    summary.max_search_s = std::max(summary.max_search_s, trial.search_seconds);
    medians.push_back(trial.median_update_ms);
  }
  summary.steps_per_trial = summary.trials > 0 ? static_cast<double>(steps) / summary.trials : 0.0;
  summary.robot_seconds = period * steps;
  std::sort(medians.begin(), medians.end());
  summary.median_update_ms = medians.empty() ? 0.0 : medians[medians.size() / 2];
  return summary;
}

int steps_for(const Config& gprca, const std::string& scenario) {
  if (!gprca.has("steps_per_trial")) return adapt::GprcaTrialsOptions{}.steps_per_trial;
  const Config per_scenario = gprca.child("steps_per_trial");
  if (per_scenario.keys().empty()) {  // one number for every scenario
    const int steps = gprca.get<int>("steps_per_trial");
    require(steps >= 1, "must be at least 1", gprca.where("steps_per_trial"));
    return steps;
  }
  int steps = 0;
  for (const std::string& name : per_scenario.keys()) {  // every entry read and checked
    const int value = per_scenario.get<int>(name);
    require(value >= 1, "must be at least 1", per_scenario.where(name));
    if (name == scenario) steps = value;
  }
  require(steps >= 1, "no steps_per_trial for " + scenario, gprca.where("steps_per_trial"));
  return steps;
}

// One summary.csv row per (goal, scenario, seed).
std::string summary_row(const RunSummary& s) {
  char row[512];
  std::snprintf(
      row, sizeof row, "%s,%s,%s,%llu,%d,%.2f,%d,%d,%.3f,%.1f,%d,%.1f,%.2f,%.3f,%.3f,%.3f\n",
      s.method.c_str(), s.goal.c_str(), s.scenario.c_str(), static_cast<unsigned long long>(s.seed),
      s.trials, s.steps_per_trial, s.goal_flag ? 1 : 0, s.collisions, s.final_distance,
      s.robot_seconds, s.oracle_trials, s.oracle_robot_seconds, s.wall_seconds, s.max_update_ms,
      s.median_update_ms, s.max_search_s);
  return row;
}

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  require(in.good(), "cannot read", file.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The output directory of this configuration: a new (or empty) one, or one an earlier run of the
// same configuration wrote (its config.yaml equal to this one), which the run continues. Anything
// else is refused: nothing is overwritten, and two configurations never share a summary.
void claim_output(const fs::path& output, const std::string& resolved) {
  const fs::path config_file = output / "config.yaml";
  if (fs::exists(output) && !fs::is_empty(output)) {
    require(fs::exists(config_file),
            "exists and is not an adaptation output; nothing is overwritten", output.string());
    require(read_run_config_text(output) == resolved,
            "holds an adaptation of another configuration (its config.yaml differs); nothing is "
            "overwritten: choose another output",
            output.string());
    std::printf("continuing %s: adaptations already written are kept\n", output.c_str());
    return;
  }
  fs::create_directories(output);
  write_run_record(output, resolved);
}

}  // namespace

int adapt_command(const Arguments& line) {
  const Config config = line.load_config(file_kind::kAdaptation);
  const std::string method = config.get<std::string>("method");
  require(method == "gprca" || method == "boac", "must be gprca or boac, got '" + method + "'",
          config.where("method"));
  const fs::path output = line.value("output", config.get_or<std::string>("output", ""));
  require(!output.empty(), "no output directory: set `output` or pass -o", config.source());
  const Config task = config.child("task");
  const Config robot = config.child("robot");
  const Config model = config.child("model");
  const Config policies = config.child("policies");
  const auto goals = config.get_or<std::vector<std::string>>("goals", {"main"});
  const auto scenarios = config.get_or<std::vector<std::string>>("scenarios", {"S0"});
  std::vector<uint64_t> seeds;
  for (int64_t seed : config.get_or<std::vector<int64_t>>("seeds", {0})) {
    require(seed >= 0, "seeds must be non-negative", config.where("seeds"));
    seeds.push_back(static_cast<uint64_t>(seed));
  }
  const double period = 0.1;  // s, the paper's 10 Hz control (PneumaticArm/Robot-v0's default)
  const Config gprca_config = config.child("gprca");
  adapt::GprcaTrialsOptions gprca_options;
  adapt::BoacOptions boac_options;
  if (method == "gprca") {
    gprca_options = adapt::read_gprca_trials_options(gprca_config);
    for (const std::string& scenario : scenarios) steps_for(gprca_config, scenario);
    gprca_config.reject_unknown();
  } else {
    boac_options = adapt::read_boac_options(config.child("boac"));
  }
  std::map<std::string, std::string> policy_files;
  for (const std::string& goal : policies.keys())
    policy_files[goal] = policies.get<std::string>(goal);
  for (const std::string& goal : goals) {
    require(policy_files.count(goal) != 0, "no trained policy for goal " + goal,
            policies.where(goal));
  }

  // task, robot and model are checked key by key by the environments built from their copies
  // (reject_unknown above), gprca and boac by their readers; here the file's own keys.
  for (const std::string& key : config.keys()) {
    static const std::vector<std::string> kKnown{"kind",  "method", "policies", "task",
                                                 "robot", "model",  "goals",    "scenarios",
                                                 "seeds", "gprca",  "boac",     "output"};
    require(std::find(kKnown.begin(), kKnown.end(), key) != kKnown.end(),
            "unknown key '" + key + "'", config.source());
  }

  const std::string resolved = config.dump_resolved();
  claim_output(output, resolved);
  const RunLock lock(output);  // one process at a time; a second is refused naming the holder
  catch_interrupts();          // Ctrl-C ends the current adaptation, then stops; rerun to continue

  std::string invocation = "tendril adapt";
  for (const std::string& arg : line.raw) invocation += " " + arg;
  std::vector<std::string> rows;
  int stopped_by = 0;
  for (const std::string& goal : goals) {
    const std::unique_ptr<rl::Policy> policy = load_trained_policy(policy_files.at(goal));
    for (const std::string& scenario : scenarios) {
      for (uint64_t seed : seeds) {
        // Each adaptation is seeded on its own: one written by an earlier, stopped run of this
        // configuration is exactly what this one would compute, and is kept.
        const fs::path directory = output / goal / scenario / ("seed_" + std::to_string(seed));
        const fs::path row_file = directory / "summary_row.csv";
        if (fs::exists(row_file)) {
          rows.push_back(file_text(row_file));
          continue;
        }
        if (stopped_by != 0) continue;
        const auto start = std::chrono::steady_clock::now();
        Config robot_params =
            assembled({&task}, {{"robot", &robot}}, config.source() + " (task, robot)");
        robot_params.set("task", goal);
        robot_params.set("robot.scenario", scenario);
        auto arm = std::make_unique<adapt::TaskReachingRobot>(
            envs::pneumatic::ReachEnv::create_on_robot(robot_params));
        robot_params.reject_unknown();
        adapt::AdaptationResult result;
        if (method == "gprca") {
          Config model_params = assembled({&task, &model}, {}, config.source() + " (task, model)");
          model_params.set("task", goal);
          adapt::TaskHistoryModel history(envs::pneumatic::ReachEnv::create_on_model(model_params));
          model_params.reject_unknown();
          adapt::GprcaTrialsOptions options = gprca_options;
          options.steps_per_trial = steps_for(gprca_config, scenario);
          result = adapt::run_gprca(*arm, history, *policy, options, seed);
        } else {
          Config model_params = assembled({&task, &model}, {}, config.source() + " (task, model)");
          model_params.set("task", goal);
          auto coach_arm = std::make_unique<adapt::TaskReachingRobot>(
              envs::pneumatic::ReachEnv::create_on_model(model_params));
          model_params.reject_unknown();
          result = adapt::run_boac(*arm, *coach_arm, *policy, boac_options, seed);
        }
        RunSummary summary = summarize(result, period);
        summary.method = method;
        summary.goal = goal;
        summary.scenario = scenario;
        summary.seed = seed;
        summary.wall_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        adapt::write_adaptation_logs(directory, result, arm->state_names());
        rows.push_back(summary_row(summary));
        write_file_atomically(row_file, rows.back(), "adaptation summary row");
        std::printf(
            "%s %-4s %s seed %llu: %2d trials of %5.1f steps, goal %s, %d collisions, final "
            "%6.2f mm; robot %5.1f s; update max %.1f ms; %.1f s wall\n",
            method.c_str(), goal.c_str(), scenario.c_str(), static_cast<unsigned long long>(seed),
            summary.trials, summary.steps_per_trial, summary.goal_flag ? "reached" : "missed",
            summary.collisions, summary.final_distance, summary.robot_seconds,
            summary.max_update_ms, summary.wall_seconds);
        std::fflush(stdout);
        stopped_by = interrupt_signal();
      }
    }
  }
  std::ostringstream csv;
  csv << "# " << invocation << "\n"
      << "method,goal,scenario,seed,trials,steps_per_trial,goal_flag,collisions,final_distance_mm,"
         "robot_s,oracle_trials,oracle_robot_s,wall_s,max_update_ms,median_update_ms,"
         "max_search_s\n";
  for (const std::string& row : rows) csv << row;
  write_file_atomically(output / "summary.csv", csv.str(), "adaptation summary");
  if (stopped_by != 0) {
    std::printf("stopped by a signal after %zu adaptations; the same command continues\n",
                rows.size());
    return 128 + stopped_by;
  }
  std::printf("wrote %s/summary.csv and the per-run logs below it\n", output.c_str());
  return 0;
}

}  // namespace tendril::apps
