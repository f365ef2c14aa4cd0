// `tendril data collect` on the pneumatic arm: the data protocol of seed 002 §III-C.
#include <cstdio>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/envs/pneumatic/collect_dataset.hpp"
#include "tendril/envs/pneumatic/reach_task.hpp"

namespace tendril::apps {

int pneumatic_collect(const Arguments& line) {
  const Config config = line.load_config(file_kind::kDataProtocol);
  std::string invocation = "tendril data collect";
  for (const std::string& arg : line.raw) invocation += " " + arg;
  const envs::pneumatic::CollectionReport report =
      envs::pneumatic::collect_pneumatic_dataset(config, line.value("output", ""), invocation);
  const auto& tips = report.data.tips_mm;
  std::printf("tendril data collect: %d rows (%.1f s of robot time) in %.2f s of wall time\n",
              report.rows,
              report.data.time_s[report.rows - 1] + (report.rows > 1 ? report.data.time_s[1] : 0.0),
              report.wall_seconds);
  std::printf("module-3 tip range [mm]: x %.1f … %.1f, y %.1f … %.1f, z %.1f … %.1f\n",
              tips.col(6).minCoeff(), tips.col(6).maxCoeff(), tips.col(7).minCoeff(),
              tips.col(7).maxCoeff(), tips.col(8).minCoeff(), tips.col(8).maxCoeff());
  // How much of the recording the seed's boundary box B (Sec. III-A) holds.
  const Eigen::AlignedBox3d boundary = envs::pneumatic::ReachTaskSpec::preset("main").boundary;
  int inside = 0;
  for (int k = 0; k < report.rows; ++k) {
    inside += boundary.contains(Eigen::Vector3d(tips(k, 6), tips(k, 7), tips(k, 8))) ? 1 : 0;
  }
  std::printf("module-3 tip inside the seed's boundary box B in %.1f %% of the rows\n",
              100.0 * inside / report.rows);
  std::printf("wrote %s\n", report.file.string().c_str());
  return 0;
}

}  // namespace tendril::apps
