#include "tendril/core/run_curves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <regex>
#include <sstream>

#include "tendril/core/error.hpp"

namespace tendril {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Linear interpolation of a curve at x inside its range (numpy.interp).
double interpolate(const Curve& c, double x) {
  const auto upper = std::upper_bound(c.x.begin(), c.x.end(), x);
  if (upper == c.x.begin()) return c.y.front();
  if (upper == c.x.end()) return c.y.back();
  const std::size_t j = static_cast<std::size_t>(upper - c.x.begin());
  const double x0 = c.x[j - 1], x1 = c.x[j];
  return x1 == x0 ? c.y[j] : c.y[j - 1] + (c.y[j] - c.y[j - 1]) * (x - x0) / (x1 - x0);
}

std::vector<std::string> split_cells(const std::string& row) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream stream(row);
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  if (!row.empty() && row.back() == ',') cells.emplace_back();
  return cells;
}

std::string column_names(const CsvColumns& table) {
  std::string names;
  for (const auto& [name, values] : table) names += (names.empty() ? "" : ", ") + name;
  return names;
}

}  // namespace

std::string seed_group(const std::string& run_name, const std::string& parent) {
  static const std::regex seed_token("(^|[-_])seed_?[0-9]+", std::regex::icase);
  static const std::regex time_stamp("[-_][0-9]{8}-[0-9]{6}$");
  std::string stripped =
      std::regex_replace(run_name, seed_token, "", std::regex_constants::format_first_only);
  stripped = std::regex_replace(stripped, time_stamp, "");
  const std::size_t first = stripped.find_first_not_of("-_");
  if (first == std::string::npos) return parent.empty() ? "seeds" : parent;
  stripped = stripped.substr(first, stripped.find_last_not_of("-_") - first + 1);
  return stripped;
}

std::vector<RunGroup> group_by_seed(const std::vector<fs::path>& runs) {
  std::vector<RunGroup> groups;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    fs::path path = runs[i].lexically_normal();
    if (path.filename().empty()) path = path.parent_path();
    const std::string parent = fs::absolute(path).parent_path().filename().string();
    const std::string name = seed_group(path.filename().string(), parent);
    auto found = std::find_if(groups.begin(), groups.end(),
                              [&](const RunGroup& group) { return group.name == name; });
    if (found == groups.end()) found = groups.insert(groups.end(), RunGroup{name, {}});
    found->members.push_back(static_cast<int>(i));
  }
  return groups;
}

Curve curve_of(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<std::pair<double, double>> points;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (std::isfinite(x[i]) && std::isfinite(y[i])) points.emplace_back(x[i], y[i]);
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  Curve curve;
  for (const auto& [a, b] : points) {
    curve.x.push_back(a);
    curve.y.push_back(b);
  }
  return curve;
}

CurveStats aggregate_curves(const std::vector<Curve>& curves, int points, CurveSpan span) {
  require(points >= 1, "the number of points must be at least 1");
  std::vector<const Curve*> present;
  for (const Curve& c : curves) {
    require(c.x.size() == c.y.size(), "a curve's x and y differ in length");
    if (!c.x.empty()) present.push_back(&c);
  }
  CurveStats stats;
  stats.curves = static_cast<int>(present.size());
  if (present.empty()) return stats;
  const bool common = span == CurveSpan::kCommon;
  double start = present.front()->x.front(), end = present.front()->x.back();
  for (const Curve* c : present) {
    start = common ? std::max(start, c->x.front()) : std::min(start, c->x.front());
    end = common ? std::min(end, c->x.back()) : std::max(end, c->x.back());
  }
  if (end < start) return stats;
  const int count = end > start ? points : 1;
  for (int i = 0; i < count; ++i) {
    const double x = count == 1 ? start : start + (end - start) * i / (count - 1);
    std::vector<double> values;
    for (const Curve* c : present) {
      if (x >= c->x.front() && x <= c->x.back()) values.push_back(interpolate(*c, x));
    }
    const Spread s = spread_of(values);
    stats.x.push_back(x);
    stats.mean.push_back(s.mean);
    stats.std.push_back(s.std);
    stats.min.push_back(s.min);
    stats.max.push_back(s.max);
    stats.count.push_back(s.count);
  }
  return stats;
}

Spread spread_of(const std::vector<double>& values) {
  Spread s;
  s.count = static_cast<int>(values.size());
  if (values.empty()) {
    s.mean = s.std = s.min = s.max = kNaN;
    return s;
  }
  s.mean = std::accumulate(values.begin(), values.end(), 0.0) / s.count;
  double squares = 0.0;
  for (const double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(squares / s.count);
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  return s;
}

CsvColumns read_csv_columns(const fs::path& file) {
  CsvColumns columns;
  std::ifstream in(file, std::ios::binary);
  if (!in) return columns;
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.erase(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
  std::istringstream lines(text);
  std::string line;
  if (!std::getline(lines, line)) return columns;
  const std::vector<std::string> header = split_cells(line);
  for (const std::string& name : header) columns[name];
  while (std::getline(lines, line)) {
    const std::vector<std::string> cells = split_cells(line);
    if (cells.size() != header.size() || cells == header) continue;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      char* end = nullptr;
      const double value = std::strtod(cells[i].c_str(), &end);
      const bool whole = !cells[i].empty() && end != nullptr && *end == 0;
      columns[header[i]].push_back(whole ? value : kNaN);
    }
  }
  return columns;
}

const std::vector<double>& column_of(const CsvColumns& table, const std::string& name) {
  static const std::vector<double> none;
  const auto found = table.find(name);
  return found == table.end() ? none : found->second;
}

Curve read_run_curve(const fs::path& run, const std::string& metric, const std::string& x_column) {
  const bool evaluation = metric == "eval" || metric.rfind("eval:", 0) == 0;
  const fs::path file = run / (evaluation ? "eval.csv" : "progress.csv");
  require(fs::is_regular_file(file), "no such file", file.string());
  const CsvColumns table = read_csv_columns(file);
  const std::string x = evaluation ? "timesteps" : x_column;
  const std::string y = metric == "eval" ? "mean_return"
                        : evaluation     ? metric.substr(std::string("eval:").size())
                                         : metric;
  for (const std::string& name : {x, y}) {
    if (table.count(name) == 0) {
      throw Error("has no column '" + name + "' (it has: " + column_names(table) + ")",
                  file.string());
    }
  }
  return curve_of(column_of(table, x), column_of(table, y));
}

}  // namespace tendril
