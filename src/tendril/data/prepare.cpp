#include "tendril/data/prepare.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "tendril/control/state_filter.hpp"
#include "tendril/core/error.hpp"
#include "tendril/data/limb_data_set.hpp"

namespace tendril::data {

const TableSchema& prepared_schema() {
  static const TableSchema schema{
      "tendril.sma_limb.prepared v1",
      {{"time_s", 3, {}, "time stamp of the reading, s"},
       {"theta_x", 6, {}, "filtered bend towards +x, deg (recursive EMA, alpha in the metadata)"},
       {"theta_y", 6, {}, "filtered bend towards +y, deg"},
       {"omega_x", 6, {}, "filtered bend rate about x, deg/s (finite difference over time_s)"},
       {"omega_y", 6, {}, "filtered bend rate about y, deg/s"},
       {"u_x", 0, {}, "x throttle from this reading to the next"},
       {"u_y", 0, {}, "y throttle from this reading to the next"},
       {"segment", 0, {}, "consecutive readings of one split without a gap share a segment"},
       {"split", 0, {"train", "test"}, "train or test set (by time, train first)"}}};
  return schema;
}

Table prepare_limb_data(const Table& data_set, const PrepareSettings& settings) {
  const char* who = "prepare";
  require(settings.test_fraction >= 0.0 && settings.test_fraction < 1.0,
          "test_fraction must lie in [0, 1)", who);
  require(std::isfinite(settings.max_gap_s) && settings.max_gap_s > 0.0,
          "max_gap_s must be positive", who);
  require(
      data_set.values.cols() == static_cast<Eigen::Index>(limb_data_set_schema().columns.size()),
      "not a limb data set", who);
  const Eigen::Index rows = data_set.rows();
  require(rows >= 1, "the data set is empty", who);
  control::StateFilter filter(settings.ema_alpha);

  const double first = data_set.values(0, 0), last = data_set.values(rows - 1, 0);
  const double split_time = first + (1.0 - settings.test_fraction) * (last - first);
  Table prepared;
  prepared.metadata = data_set.metadata;
  char text[64];
  std::snprintf(text, sizeof text, "%g", settings.ema_alpha);
  prepared.set("ema_alpha", text);
  std::snprintf(text, sizeof text, "%g", settings.test_fraction);
  prepared.set("test_fraction", text);
  std::snprintf(text, sizeof text, "%.3f", split_time);
  prepared.set("split_time_s", text);
  std::snprintf(text, sizeof text, "%g", settings.max_gap_s);
  prepared.set("max_gap_s", text);
  prepared.values.resize(rows, static_cast<Eigen::Index>(prepared_schema().columns.size()));

  int segment = -1;
  double previous_split = -1.0;
  for (Eigen::Index r = 0; r < rows; ++r) {
    const double time = data_set.values(r, 0);
    const double split = settings.test_fraction > 0.0 && time >= split_time ? kTest : kTrain;
    if (r == 0 || split != previous_split ||
        time - data_set.values(r - 1, 0) > settings.max_gap_s) {
      ++segment;
      filter.reset();
    }
    previous_split = split;
    const Eigen::Vector4d state =
        filter.update(time, Eigen::Vector2d(data_set.values(r, 1), data_set.values(r, 2)));
    prepared.values.row(r) << time, state.transpose(), data_set.values(r, 3), data_set.values(r, 4),
        segment, split;
  }
  return prepared;
}

Table read_prepared(const std::filesystem::path& file) {
  return read_table(file, prepared_schema());
}

void write_prepared(const std::filesystem::path& file, const Table& table) {
  write_table(file, table, prepared_schema());
}

}  // namespace tendril::data
