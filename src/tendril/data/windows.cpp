#include "tendril/data/windows.hpp"

#include "tendril/core/error.hpp"
#include "tendril/data/prepare.hpp"

namespace tendril::data {

void WindowSet::gather(const std::vector<int64_t>& indices, Features& batch,
                       Labels& batch_labels) const {
  batch.resize(static_cast<Eigen::Index>(indices.size()) * history, kFeatures);
  batch_labels.resize(static_cast<Eigen::Index>(indices.size()), kState);
  for (std::size_t b = 0; b < indices.size(); ++b) {
    const std::size_t i = static_cast<std::size_t>(indices[b]);
    if (i >= size())
      throw Error("window " + std::to_string(i) + " of " + std::to_string(size()),
                  "WindowSet::gather");
    batch.middleRows(static_cast<Eigen::Index>(b) * history, history) = window(i);
    batch_labels.row(static_cast<Eigen::Index>(b)) = labels.row(static_cast<Eigen::Index>(i));
  }
}

WindowSet build_windows(const Table& prepared, int history, double split) {
  require(history >= 1, "history must be at least 1", "build_windows");
  require(prepared.values.cols() == static_cast<Eigen::Index>(prepared_schema().columns.size()),
          "not a prepared data set", "build_windows");
  WindowSet set;
  set.history = history;
  const Eigen::Index rows = prepared.rows();
  set.features.resize(rows, WindowSet::kFeatures);
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (int f = 0; f < WindowSet::kFeatures; ++f) {
      set.features(r, f) = static_cast<float>(prepared.values(r, kThetaX + f));
    }
  }
  std::vector<float> labels;
  Eigen::Index segment_start = 0;
  for (Eigen::Index k = 0; k + 1 < rows; ++k) {
    if (k > 0 && prepared.values(k, kSegment) != prepared.values(k - 1, kSegment)) {
      segment_start = k;
    }
    if (prepared.values(k, kSplit) != split) continue;
    if (prepared.values(k + 1, kSegment) != prepared.values(k, kSegment)) continue;
    if (k - segment_start + 1 < history) continue;
    set.ends.push_back(k);
    for (int s = 0; s < WindowSet::kState; ++s) {
      labels.push_back(static_cast<float>(prepared.values(k + 1, kThetaX + s) -
                                          prepared.values(k, kThetaX + s)));
    }
  }
  set.labels = Eigen::Map<const WindowSet::Labels>(
      labels.data(), static_cast<Eigen::Index>(set.ends.size()), WindowSet::kState);
  return set;
}

}  // namespace tendril::data
