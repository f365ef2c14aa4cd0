// The tasks of `tendril data` behind the thesis' figures: open-loop replays after cool-downs
// (Fig. 1.1c), exploration against babbling (Fig. 4.2) and the limb's response to the open-loop
// test inputs (Fig. 4.4's ground truth).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "collect_support.hpp"
#include "tendril/control/state_filter.hpp"
#include "tendril/core/data_table.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/data/prepare.hpp"
#include "tendril/envs/sma_limb/open_loop_inputs.hpp"

namespace tendril::apps::collect {

namespace {

struct Segment {
  double duration_s = 0.0;
  int u_x = 0, u_y = 0;
};

struct Trace {
  std::vector<double> time_s;  // since the sequence began
  std::vector<Eigen::Vector2d> angles_deg;
  std::vector<Eigen::Vector2i> throttles;
};

Action throttles(int ux, int uy) {
  Action action(2);
  action << static_cast<float>(ux), static_cast<float>(uy);
  return action;
}

double time_of(const Step& step) { return *step.info.get("time_s"); }

// Drives `env` through the segments from its current reading (`now`, its time stamp).
Trace run_sequence(Env& env, const std::vector<Segment>& segments, double& now,
                   Observation& observation) {
  Trace trace;
  const double start = now;
  double end = start;
  for (const Segment& segment : segments) {
    end += segment.duration_s;
    while (now < end) {
      trace.time_s.push_back(now - start);
      trace.angles_deg.push_back(observation.head<2>().cast<double>());
      trace.throttles.push_back(Eigen::Vector2i(segment.u_x, segment.u_y));
      const Step step = env.step(throttles(segment.u_x, segment.u_y));
      observation = step.observation;
      now = time_of(step);
    }
  }
  return trace;
}

// RMSE and largest distance (deg) of `replay` from `original`, interpolated at replay's times.
Eigen::Vector2d deviation(const Trace& original, const Trace& replay) {
  double squares = 0.0, largest = 0.0;
  int count = 0;
  std::size_t j = 0;
  for (std::size_t i = 0; i < replay.time_s.size(); ++i) {
    const double t = replay.time_s[i];
    while (j + 2 < original.time_s.size() && original.time_s[j + 1] < t) ++j;
    if (j + 1 >= original.time_s.size() || t > original.time_s.back()) break;
    const double w = std::clamp(
        (t - original.time_s[j]) / (original.time_s[j + 1] - original.time_s[j]), 0.0, 1.0);
    const Eigen::Vector2d at = (1.0 - w) * original.angles_deg[j] + w * original.angles_deg[j + 1];
    const double distance = (replay.angles_deg[i] - at).norm();
    squares += distance * distance;
    largest = std::max(largest, distance);
    ++count;
  }
  return Eigen::Vector2d(std::sqrt(squares / std::max(count, 1)), largest);
}

}  // namespace

int replay(const Config& config) {
  std::vector<Segment> segments;
  for (const Config& entry : config.children("segments")) {
    segments.push_back(
        {entry.get<double>("duration_s"), entry.get<int>("u_x"), entry.get<int>("u_y")});
    require(segments.back().duration_s > 0.0, "segment durations must be positive",
            where(entry, "duration_s"));
  }
  require(!segments.empty(), "list at least one segment", where(config, "segments"));
  const std::vector<double> cooldowns = config.get<std::vector<double>>("cooldowns_s");
  for (double c : cooldowns)
    require(c >= 0.0, "cool-downs must be >= 0", where(config, "cooldowns_s"));
  const uint64_t seed = config.get<uint64_t>("seed");
  auto env = limb_env(config);
  const std::string limb = config.child("env").get_or<std::string>("limb", "stiff");
  const std::filesystem::path output = new_output(config, "output");
  config.reject_unknown();

  const Stopwatch stopwatch;
  Observation observation = env->reset(seed);
  double now = 0.0;
  std::vector<Trace> traces{run_sequence(*env, segments, now, observation)};
  std::vector<std::string> runs{"original"};
  // Every replay starts from the state right after the original: the robot is switched off for
  // the cool-down, then given the same throttles.
  Snapshot after_original;
  SnapshotWriter writer(after_original);
  env->save_state(writer);
  const Observation observation_after = observation;
  const double time_after = now;
  double robot_time = now;
  std::printf("tendril data replay: replaying %zu segments (%.1f s) on the %s limb\n",
              segments.size(), traces[0].time_s.back(), limb.c_str());
  for (double cooldown : cooldowns) {
    SnapshotReader reader(after_original);
    env->load_state(reader);
    observation = observation_after;
    now = time_after;
    while (now < time_after + cooldown) {
      const Step step = env->step(throttles(0, 0));
      observation = step.observation;
      now = time_of(step);
    }
    traces.push_back(run_sequence(*env, segments, now, observation));
    runs.push_back("after_" + number(cooldown) + "s_cooldown");
    const Eigen::Vector2d off = deviation(traces[0], traces.back());
    std::printf("after a %.0f s cool-down: RMSE %.2f deg from the original, largest %.2f deg\n",
                cooldown, off[0], off[1]);
    robot_time += now - time_after;
  }
  stopwatch.report(robot_time);

  const data::TableSchema schema{"tendril.sma_limb.replay v1",
                                 {{"run", 0, runs, "original, or the replay after that cool-down"},
                                  {"time_s", 3, {}, "since the run's throttle sequence began, s"},
                                  {"theta_x_deg", 2, {}, "bend reading towards +x, deg"},
                                  {"theta_y_deg", 2, {}, "bend reading towards +y, deg"},
                                  {"u_x", 0, {}, "x throttle"},
                                  {"u_y", 0, {}, "y throttle"}}};
  data::Table table;
  table.set("limb", limb);
  table.set("seed", std::to_string(seed));
  table.set("config", config.source());
  std::size_t rows = 0;
  for (const Trace& trace : traces) rows += trace.time_s.size();
  table.values.resize(static_cast<Eigen::Index>(rows), 6);
  Eigen::Index r = 0;
  for (std::size_t run = 0; run < traces.size(); ++run) {
    const Trace& trace = traces[run];
    for (std::size_t k = 0; k < trace.time_s.size(); ++k, ++r) {
      table.values.row(r) << static_cast<double>(run), std::round(trace.time_s[k] * 1e3) / 1e3,
          std::round(trace.angles_deg[k].x() * 100.0) / 100.0,
          std::round(trace.angles_deg[k].y() * 100.0) / 100.0, trace.throttles[k].x(),
          trace.throttles[k].y();
    }
  }
  data::write_table(output, table, schema);
  std::printf("wrote %s\n", output.c_str());
  return 0;
}

int open_loop(const Config& config) {
  const std::vector<std::string> inputs = config.get<std::vector<std::string>>("inputs");
  require(!inputs.empty(), "list at least one input", where(config, "inputs"));
  const int64_t steps = config.get_or<int64_t>("steps", 800);
  const double amplitude = config.get_or<double>("amplitude", 10.0);
  const double ema_alpha = config.get_or<double>("ema_alpha", 0.8);
  std::vector<envs::sma_limb::ThrottleSequence> sequences;
  for (const std::string& kind : inputs) {
    try {
      sequences.push_back(envs::sma_limb::open_loop_inputs(kind, steps, amplitude));
    } catch (const Error& e) {
      throw Error(e.what_wrong(), where(config, "inputs"));
    }
  }
  const uint64_t seed = config.get<uint64_t>("seed");
  auto env = limb_env(config);
  const std::string limb = config.child("env").get_or<std::string>("limb", "stiff");
  const std::filesystem::path output = new_output(config, "output");
  config.reject_unknown();

  // A prepared data set's columns up to the throttles (time since the input began): the columns
  // of a model's open-loop rollout (`tendril dynamics eval --open-loop`).
  data::TableSchema schema = data::prepared_schema();
  schema.format = "tendril.sma_limb.open_loop v1";
  schema.columns.resize(data::kUy + 1);
  std::filesystem::create_directories(output);
  const Stopwatch stopwatch;
  double robot_time = 0.0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const envs::sma_limb::LimbLog log = envs::sma_limb::drive_open_loop(*env, sequences[i], seed);
    data::Table table;
    table.set("limb", limb);
    table.set("input", inputs[i]);
    table.set("seed", std::to_string(seed));
    table.set("ema_alpha", number(ema_alpha));
    table.set("config", config.source());
    table.values.resize(static_cast<Eigen::Index>(log.size()), data::kUy + 1);
    control::StateFilter filter(ema_alpha);
    for (std::size_t k = 0; k < log.size(); ++k) {
      const Eigen::Vector4d state = filter.update(log.time_s[k], log.angles_deg[k]);
      table.values.row(static_cast<Eigen::Index>(k)) << log.time_s[k], state.transpose(),
          log.throttles[k].x(), log.throttles[k].y();
    }
    const std::filesystem::path file = output / ("open_loop_" + inputs[i] + ".csv");
    data::write_table(file, table, schema);
    robot_time += log.time_s.back();
    std::printf("%-8s %zu readings over %.1f s, end state %.1f, %.1f deg -> %s\n",
                inputs[i].c_str(), log.size(), log.time_s.back(), log.angles_deg.back().x(),
                log.angles_deg.back().y(), file.c_str());
  }
  stopwatch.report(robot_time);
  return 0;
}

int compare_coverage(const Config& config) {
  const envs::sma_limb::CollectSettings settings = collect_settings(config);
  const std::vector<int64_t> seeds = config.get<std::vector<int64_t>>("seeds");
  require(!seeds.empty(), "list at least one seed", where(config, "seeds"));
  limb_env(config);  // reads and checks the env parameters before anything runs
  const std::string limb = config.child("env").get_or<std::string>("limb", "stiff");
  const std::filesystem::path output = new_output(config, "output");
  const std::filesystem::path points = new_output(config, "points");
  throttle_source("explore", config);  // reads `rule`
  config.reject_unknown();

  std::printf(
      "tendril data coverage: exploration against babbling on the %s limb, %.0f s each, "
      "seeds",
      limb.c_str(), settings.duration_s);
  for (int64_t seed : seeds) std::printf(" %lld", static_cast<long long>(seed));
  std::printf("\n%-9s %6s %8s %9s %8s\n", "source", "seed", "cells", "evenness", "cutoffs");
  const Stopwatch stopwatch;
  const std::vector<std::string> sources{"explore", "babble"};
  std::vector<std::array<double, 5>> summary;  // source, seed, cells, evenness, cutoffs
  std::vector<std::array<double, 4>> cloud;    // source, time, θx, θy (the first seed)
  double robot_time = 0.0;
  for (int64_t seed : seeds) {
    for (std::size_t s = 0; s < sources.size(); ++s) {
      auto env = limb_env(config);
      auto source = throttle_source(sources[s], config);
      const envs::sma_limb::LimbLog log =
          envs::sma_limb::collect(*env, *source, settings, static_cast<uint64_t>(seed));
      robot_time += log.time_s.back();
      const auto grid = coverage(log, settings.duration_s);
      summary.push_back({static_cast<double>(s), static_cast<double>(seed),
                         static_cast<double>(grid.visited_cells()), grid.evenness(),
                         static_cast<double>(log.cutoffs)});
      std::printf("%-9s %6lld %8d %9.3f %8lld\n", sources[s].c_str(), static_cast<long long>(seed),
                  grid.visited_cells(), grid.evenness(), static_cast<long long>(log.cutoffs));
      if (seed != seeds.front()) continue;
      for (std::size_t k = 0; k < log.size(); ++k) {
        cloud.push_back({static_cast<double>(s), std::round(log.time_s[k] * 1e3) / 1e3,
                         std::round(log.angles_deg[k].x() * 100.0) / 100.0,
                         std::round(log.angles_deg[k].y() * 100.0) / 100.0});
      }
    }
  }
  int wins = 0;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    double sum = 0.0, squares = 0.0;
    for (const auto& row : summary) {
      if (row[0] != static_cast<double>(s)) continue;
      sum += row[3];
      squares += row[3] * row[3];
    }
    const double n = static_cast<double>(seeds.size());
    const double mean = sum / n;
    const double spread =
        n > 1 ? std::sqrt(std::max(0.0, (squares - n * mean * mean) / (n - 1))) : 0.0;
    std::printf("%-9s evenness %.3f +- %.3f (mean +- sample std over %zu seeds)\n",
                sources[s].c_str(), mean, spread, seeds.size());
  }
  for (std::size_t i = 0; i + 1 < summary.size(); i += 2) wins += summary[i][3] > summary[i + 1][3];
  std::printf("exploration more even than babbling on %d of %zu seeds\n", wins, seeds.size());
  stopwatch.report(robot_time);

  const std::vector<std::string> words{"explore", "babble"};
  const data::TableSchema summary_schema{
      "tendril.sma_limb.coverage v1",
      {{"source", 0, words, "count-based exploration or motor babbling"},
       {"seed", 0, {}, "collection seed"},
       {"cells", 0, {}, "cells of the 6x6 grid over +-100 deg visited at least once"},
       {"evenness", 4, {}, "visit entropy / log 36 (1: every cell equally often)"},
       {"cutoffs", 0, {}, "readings past the 100 deg cut-off"}}};
  const data::TableSchema points_schema{
      "tendril.sma_limb.coverage_points v1",
      {{"source", 0, words, "count-based exploration or motor babbling"},
       {"time_s", 3, {}, "reading time stamp, s"},
       {"theta_x_deg", 2, {}, "bend reading towards +x, deg"},
       {"theta_y_deg", 2, {}, "bend reading towards +y, deg"}}};
  data::Table summary_table, points_table;
  for (data::Table* table : {&summary_table, &points_table}) {
    table->set("limb", limb);
    table->set("duration_s", number(settings.duration_s));
    table->set("cutoff_cooldown_s", number(settings.cutoff_cooldown_s));
    table->set("config", config.source());
  }
  points_table.set("seed", std::to_string(seeds.front()));
  summary_table.values.resize(static_cast<Eigen::Index>(summary.size()), 5);
  for (std::size_t r = 0; r < summary.size(); ++r) {
    for (int c = 0; c < 5; ++c)
      summary_table.values(static_cast<Eigen::Index>(r), c) = summary[r][c];
  }
  points_table.values.resize(static_cast<Eigen::Index>(cloud.size()), 4);
  for (std::size_t r = 0; r < cloud.size(); ++r) {
    for (int c = 0; c < 4; ++c) points_table.values(static_cast<Eigen::Index>(r), c) = cloud[r][c];
  }
  data::write_table(output, summary_table, summary_schema);
  data::write_table(points, points_table, points_schema);
  std::printf("wrote %s and %s\n", output.c_str(), points.c_str());
  return 0;
}

}  // namespace tendril::apps::collect
