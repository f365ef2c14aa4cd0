#include "tendril/dynamics/evaluation.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/core/error.hpp"
#include "tendril/envs/learned/history_windows.hpp"

namespace tendril::dynamics {

namespace {

// Accumulates squared errors per group.
struct SquaredErrors {
  explicit SquaredErrors(std::vector<StateGroup> groups)
      : groups(std::move(groups)), sums(this->groups.size(), 0.0), counts(this->groups.size(), 0) {}

  template <typename Predicted, typename Recorded>
  void add(const Predicted& predicted, const Recorded& recorded) {
    for (std::size_t g = 0; g < groups.size(); ++g) {
      for (int c : groups[g].columns) {
        const double error = static_cast<double>(predicted[c]) - static_cast<double>(recorded[c]);
        sums[g] += error * error;
        ++counts[g];
      }
    }
  }

  ErrorReport report(int64_t points, int64_t starts) const {
    ErrorReport result;
    result.groups = groups;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      // A model whose outputs overflow (or a crafted file that slipped past the loader's checks)
      // must not pass as an error of "nan".
      if (counts[g] > 0 && !std::isfinite(sums[g])) {
        throw Error("the model's predictions of " + groups[g].name +
                        " are not finite (NaN or infinity): no error can be measured",
                    "dynamics evaluation");
      }
      result.rmse.push_back(counts[g] ? std::sqrt(sums[g] / static_cast<double>(counts[g]))
                                      : std::nan(""));
    }
    result.points = points;
    result.rollouts = starts;
    return result;
  }

  std::vector<StateGroup> groups;
  std::vector<double> sums;
  std::vector<int64_t> counts;
};

// The pieces rollout_errors rolls out: each segment of `split` cut into consecutive pieces of
// `horizon` seconds of recorded time, each started at the row that completes its first window.
void rollout_pieces(const SequenceData& data, Split split, double horizon, double max_gap, int n,
                    std::vector<int64_t>& starts, std::vector<int64_t>& steps) {
  require(horizon > 0.0, "the rollout horizon must be positive", "dynamics::rollout_errors");
  for (const Segment& segment : data.segments(max_gap)) {
    if (segment.split != split) continue;
    int64_t start = segment.begin + n - 1;
    while (start + 1 < segment.end) {
      int64_t end = start;
      while (end + 1 < segment.end && data.time(end + 1) - data.time(start) <= horizon) ++end;
      if (end == start) break;
      starts.push_back(start);
      steps.push_back(end - start);
      start = end;
    }
  }
}

std::vector<int64_t> kept_ends(const std::vector<int64_t>& ends, const PointFilter& include) {
  std::vector<int64_t> kept;
  for (int64_t t : ends) {
    if (include(t)) kept.push_back(t);
  }
  return kept;
}

ErrorReport one_step_errors_at(Model& model, const WindowSet& windows,
                               const std::vector<int64_t>& ends, int batch_size,
                               const Progress& on_progress);

}  // namespace

std::vector<StateGroup> state_groups(const std::vector<std::string>& state_names) {
  StateGroup angle{"angle", "deg", {}}, velocity{"velocity", "deg/s", {}};
  std::vector<StateGroup> others;
  for (int c = 0; c < static_cast<int>(state_names.size()); ++c) {
    const std::string& name = state_names[c];
    if (name.rfind("theta_", 0) == 0) {
      angle.columns.push_back(c);
    } else if (name.rfind("omega_", 0) == 0) {
      velocity.columns.push_back(c);
    } else {
      others.push_back(StateGroup{name, "", {c}});
    }
  }
  std::vector<StateGroup> groups;
  if (!angle.columns.empty()) groups.push_back(angle);
  if (!velocity.columns.empty()) groups.push_back(velocity);
  groups.insert(groups.end(), others.begin(), others.end());
  return groups;
}

ErrorReport one_step_errors(Model& model, const WindowSet& windows, Split split, int batch_size,
                            const PointFilter& include, const Progress& on_progress) {
  if (include) {
    const std::vector<int64_t> kept = kept_ends(windows.ends(split), include);
    return one_step_errors_at(model, windows, kept, batch_size, on_progress);
  }
  return one_step_errors_at(model, windows, windows.ends(split), batch_size, on_progress);
}

ErrorReport persistence_one_step_errors(const SequenceData& data, const WindowSet& windows,
                                        Split split, const PointFilter& include) {
  SquaredErrors errors(state_groups(data.state_names));
  int64_t count = 0;
  for (int64_t t : windows.ends(split)) {
    if (include && !include(t)) continue;
    errors.add(data.states.row(t), data.states.row(t + 1));
    ++count;
  }
  return errors.report(count, count);
}

ErrorReport persistence_rollout_errors(const SequenceData& data, Split split, double horizon,
                                       double max_gap, int window_length) {
  std::vector<int64_t> starts, steps;
  rollout_pieces(data, split, horizon, max_gap, window_length, starts, steps);
  SquaredErrors errors(state_groups(data.state_names));
  int64_t points = 0;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    for (int64_t k = 0; k < steps[i]; ++k) {
      errors.add(data.states.row(starts[i]), data.states.row(starts[i] + 1 + k));
    }
    points += steps[i];
  }
  return errors.report(points, static_cast<int64_t>(starts.size()));
}

bool input_changed_within(const SequenceData& data, int64_t t, int readings) {
  for (int64_t k = t; k > t - readings && k >= 1; --k) {
    if (data.inputs.row(k) != data.inputs.row(k - 1)) return true;
  }
  return false;
}

namespace {

ErrorReport one_step_errors_at(Model& model, const WindowSet& windows,
                               const std::vector<int64_t>& ends, int batch_size,
                               const Progress& on_progress) {
  SquaredErrors errors(state_groups(model.description().state_names));
  for (std::size_t begin = 0; begin < ends.size(); begin += static_cast<std::size_t>(batch_size)) {
    const std::span<const int64_t> batch(ends.data() + begin,
                                         std::min<std::size_t>(batch_size, ends.size() - begin));
    const torch::Tensor predicted = model.predict(windows.windows(batch)).contiguous();
    const torch::Tensor recorded = windows.next_states(batch).contiguous();
    const auto p = predicted.accessor<float, 2>();
    const auto r = recorded.accessor<float, 2>();
    for (int64_t i = 0; i < predicted.size(0); ++i) errors.add(p[i], r[i]);
    if (on_progress) {
      on_progress(static_cast<double>(begin + batch.size()) / static_cast<double>(ends.size()));
    }
  }
  const auto count = static_cast<int64_t>(ends.size());
  return errors.report(count, count);
}

}  // namespace

std::vector<RowMatrixXd> rollouts(Model& model, const SequenceData& data,
                                  const std::vector<int64_t>& starts,
                                  const std::vector<int64_t>& steps, const Progress& on_progress) {
  require(starts.size() == steps.size() && !starts.empty(), "needs one step count per start",
          "dynamics::rollouts");
  const int n = model.window_length(), dx = model.state_dim(), du = model.input_dim();
  const auto envs = static_cast<int>(starts.size());
  envs::HistoryWindows windows(envs, n, dx, du);
  for (int i = 0; i < envs; ++i) {
    require(starts[i] >= n - 1 && starts[i] + steps[i] < data.rows() && steps[i] >= 0,
            "rollout from row " + std::to_string(starts[i]) + " for " + std::to_string(steps[i]) +
                " steps leaves the data",
            data.source);
    envs::BatchMatrix rows(n, dx + du);
    for (int k = 0; k < n; ++k) {
      const int64_t t = starts[i] - (n - 1) + k;
      rows.row(k).head(dx) = data.states.row(t).cast<float>();
      rows.row(k).tail(du) = data.inputs.row(t).cast<float>();
    }
    windows.set_window(i, rows);
  }
  std::vector<RowMatrixXd> predicted(envs);
  for (int i = 0; i < envs; ++i) predicted[i].resize(steps[i], dx);
  const int64_t longest = *std::max_element(steps.begin(), steps.end());
  envs::BatchMatrix inputs(envs, du), next;
  for (int64_t k = 0; k < longest; ++k) {
    for (int i = 0; i < envs; ++i) {
      // A finished rollout keeps stepping on its last input; its predictions are not kept.
      const int64_t t = starts[i] + std::min(k, steps[i] - 1);
      inputs.row(i) = data.inputs.row(std::max<int64_t>(t, 0)).cast<float>();
    }
    model.step(windows, inputs, next);
    for (int i = 0; i < envs; ++i) {
      if (k < steps[i]) predicted[i].row(k) = next.row(i).cast<double>();
    }
    if (on_progress) on_progress(static_cast<double>(k + 1) / static_cast<double>(longest));
  }
  return predicted;
}

ErrorReport rollout_errors(Model& model, const SequenceData& data, Split split, double horizon,
                           double max_gap, const Progress& on_progress) {
  std::vector<int64_t> starts, steps;
  rollout_pieces(data, split, horizon, max_gap, model.window_length(), starts, steps);
  SquaredErrors errors(state_groups(model.description().state_names));
  if (starts.empty()) return errors.report(0, 0);
  const std::vector<RowMatrixXd> predicted = rollouts(model, data, starts, steps, on_progress);
  int64_t points = 0;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    for (int64_t k = 0; k < steps[i]; ++k) {
      errors.add(predicted[i].row(k), data.states.row(starts[i] + 1 + k));
    }
    points += steps[i];
  }
  return errors.report(points, static_cast<int64_t>(starts.size()));
}

}  // namespace tendril::dynamics
