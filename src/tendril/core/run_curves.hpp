#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

// Learning curves of runs and their statistics over seeds: the one implementation behind the
// sweep summaries (`tendril sweep summary`, `tendril report`), the figures of `tendril plot
// curves` (python/tendril_plot, through the Python extension) and the dashboard's grouped curves
// (`tendril serve`, /api/curves).
namespace tendril {

// A run's name without its seed token, a trailing time stamp and the separators left at its ends,
// the group of runs that differ only by seed: "n_steps_256-seed_3" → "n_steps_256",
// "ppo_case1_seed0" → "ppo_case1", "seed_3-tau_0.01" → "tau_0.01", "ppo-seed1-20261128-093000"
// → "ppo" (`tendril train`'s default name); a name that is only a seed ("seed_42") gives
// `parent`, the name of the directory holding the run, or "seeds".
std::string seed_group(const std::string& run_name, const std::string& parent = "");

// Runs grouped by seed_group of their directory names (with the name of the directory holding
// each), groups in order of first appearance, runs in the order given.
struct RunGroup {
  std::string name;
  std::vector<int> members;  // indices into the runs given
};
std::vector<RunGroup> group_by_seed(const std::vector<std::filesystem::path>& runs);

// A curve of one run: y against environment steps, x ascending.
struct Curve {
  std::vector<double> x, y;
};

// The finite (x, y) pairs of two columns, sorted by x (stably).
Curve curve_of(const std::vector<double>& x, const std::vector<double>& y);

// Which x values a group's statistics span:
// - kCommon: the range every curve covers, so each point averages every curve (the figures and
//   summaries of finished runs);
// - kAny: the range any curve covers, each point averaging the curves that reach it (a live view,
//   where a run still training must not shorten the others).
enum class CurveSpan { kCommon, kAny };

// Mean, population standard deviation, minimum and maximum over curves at `points` evenly spaced
// x values, by linear interpolation, with the number of curves behind each point. Empty curves
// are left out (`curves` counts the others); `x` is empty when none is left or, for kCommon, their
// ranges do not overlap.
struct CurveStats {
  std::vector<double> x, mean, std, min, max;
  std::vector<int> count;
  int curves = 0;
};
CurveStats aggregate_curves(const std::vector<Curve>& curves, int points = 200,
                            CurveSpan span = CurveSpan::kCommon);

// Mean, population standard deviation, minimum and maximum of numbers (NaN for none).
struct Spread {
  double mean = 0.0, std = 0.0, min = 0.0, max = 0.0;
  int count = 0;
};
Spread spread_of(const std::vector<double>& values);

// The numeric columns of a run's CSV file (progress.csv, eval.csv) by header name; empty when the
// file is missing. Cells that are not numbers read as NaN; a last line without its newline (a file
// being written) and rows with the wrong number of cells are left out.
using CsvColumns = std::map<std::string, std::vector<double>>;
CsvColumns read_csv_columns(const std::filesystem::path& file);
// A column of `table`, or an empty one.
const std::vector<double>& column_of(const CsvColumns& table, const std::string& name);

// One curve of a run directory, the metrics `tendril plot curves` and the dashboard name:
// "eval" (eval.csv's mean_return against timesteps), "eval:<column>" (another eval.csv column),
// or a progress.csv column against `x_column`. Error naming the file and the columns it has when
// the metric or x column is not there.
Curve read_run_curve(const std::filesystem::path& run, const std::string& metric,
                     const std::string& x_column = "time/total_timesteps");

}  // namespace tendril
