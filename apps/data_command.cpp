// `tendril data collect|calibrate|replay|coverage|open-loop|prepare`: the data protocols of the
// robots, each named by its verb; the YAML file says which robot (SMA limb files carry the
// protocol in `task:`, which must match the verb; pneumatic-arm and tendon-arm files name
// `robot.id`).
#include <cstdio>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"
#include "tendril/envs/tendon_arm/collect_dataset.hpp"

namespace tendril::apps {

// The SMA limb's protocols (collect_command.cpp) and the pneumatic arm's.
int limb_protocol(const Arguments& line, const std::vector<std::string>& tasks);
int pneumatic_collect(const Arguments& line);
int pneumatic_replay(const Arguments& line);

namespace {

// SMA limb files name their protocol in `task:` and their outputs in the file.
bool is_limb_file(const Arguments& line) {
  const bool limb = line.load_config(file_kind::kDataProtocol).has("task");
  require(!limb || !line.has("output"),
          "an SMA limb file names its outputs itself: change them with --set output=...",
          "--output");
  return limb;
}

// The tendon arm's files name a TendonArm/ robot (envs/tendon_arm/collect_dataset.hpp).
int tendon_arm_collect(const Arguments& line) {
  std::string invocation = "tendril data collect";
  for (const std::string& arg : line.raw) invocation += " " + arg;
  const auto report = envs::tendon_arm::collect_dataset(line.load_config(file_kind::kDataProtocol),
                                                        line.value("output", ""), invocation);
  std::printf("tendril data collect: %d training and %d test rows in %.2f s of wall time\n",
              report.train_rows, report.test_rows, report.wall_seconds);
  std::printf("wrote %s\n", report.file.string().c_str());
  return 0;
}

}  // namespace

int data_collect_command(const Arguments& line) {
  if (is_limb_file(line)) return limb_protocol(line, {"explore", "babble"});
  const std::string robot =
      line.load_config(file_kind::kDataProtocol).child("robot").get_or<std::string>("id", "");
  if (robot.rfind("TendonArm/", 0) == 0) return tendon_arm_collect(line);
  return pneumatic_collect(line);
}

int data_calibrate_command(const Arguments& line) { return limb_protocol(line, {"calibrate"}); }

int data_replay_command(const Arguments& line) {
  return is_limb_file(line) ? limb_protocol(line, {"replay"}) : pneumatic_replay(line);
}

int data_coverage_command(const Arguments& line) { return limb_protocol(line, {"coverage"}); }

int data_open_loop_command(const Arguments& line) { return limb_protocol(line, {"open_loop"}); }

}  // namespace tendril::apps
