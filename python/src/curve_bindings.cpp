// Runs grouped by seed and curves aggregated over seeds (core/run_curves), for the figures of
// `tendril plot curves` (python/tendril_plot): the statistics the sweep summaries and the
// dashboard show, computed by the same code.
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/run_curves.hpp"

namespace py = pybind11;

namespace tendril::python {

void bind_curves(py::module_& m) {
  m.def("seed_group", &seed_group, py::arg("run_name"), py::arg("parent") = "",
        "A run's name without its seed token and time stamp: the group of runs that differ only "
        "by seed ('seed_42' alone gives `parent`, or 'seeds').");
  m.def(
      "aggregate_curves",
      [](const std::vector<std::pair<std::vector<double>, std::vector<double>>>& given, int points,
         const std::string& span) {
        require(span == "common" || span == "any", "span must be 'common' or 'any'", span);
        std::vector<Curve> curves;
        for (const auto& [x, y] : given) curves.push_back(Curve{x, y});
        const CurveStats stats = aggregate_curves(
            curves, points, span == "common" ? CurveSpan::kCommon : CurveSpan::kAny);
        py::dict result;
        result["x"] = stats.x;
        result["mean"] = stats.mean;
        result["std"] = stats.std;
        result["min"] = stats.min;
        result["max"] = stats.max;
        result["count"] = stats.count;
        result["curves"] = stats.curves;
        return result;
      },
      py::arg("curves"), py::arg("points") = 200, py::arg("span") = "common",
      "Mean, population std, min and max of (x, y) curves (x ascending) at `points` evenly "
      "spaced x values, by linear interpolation: over the range every curve covers ('common') "
      "or any covers ('any', each point from the curves reaching it; 'count' says how many).");
}

}  // namespace tendril::python
