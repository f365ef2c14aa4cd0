#pragma once

#include <string>
#include <vector>

#include "tendril/sweeps/sweep_summary.hpp"

namespace tendril::sweeps {

// A Markdown report of runs (`tendril report`): per configuration, the mean ± standard
// deviation over its runs of the training mean at each of `steps` and at the end, of the final
// evaluation, and its training time; then the same per run, with its steps/s. A training mean
// at a step is training_mean_at's; a run that has not reached the step has none there.
std::string runs_report(const SweepSummary& summary, const std::vector<double>& steps);

}  // namespace tendril::sweeps
