// `tendril data collect|calibrate|replay|coverage|open-loop|prepare`: the data protocols of the
// robots, each named by its verb; the YAML file says which robot (SMA limb files carry the
// protocol in `task:`, which must match the verb; pneumatic-arm files name `robot.id`).
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/file_kind.hpp"

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

}  // namespace

int data_collect_command(const Arguments& line) {
  return is_limb_file(line) ? limb_protocol(line, {"explore", "babble"}) : pneumatic_collect(line);
}

int data_calibrate_command(const Arguments& line) { return limb_protocol(line, {"calibrate"}); }

int data_replay_command(const Arguments& line) {
  return is_limb_file(line) ? limb_protocol(line, {"replay"}) : pneumatic_replay(line);
}

int data_coverage_command(const Arguments& line) { return limb_protocol(line, {"coverage"}); }

int data_open_loop_command(const Arguments& line) { return limb_protocol(line, {"open_loop"}); }

}  // namespace tendril::apps
