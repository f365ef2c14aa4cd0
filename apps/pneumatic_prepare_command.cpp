// `tendril data prepare`: the pneumatic arm's recordings as the learned-dynamics layer's
// prepared data set (the file configs/dynamics/pneumatic_softsign_lstm.yaml reads).
#include <cstdio>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/prepared_csv.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"

namespace tendril::apps {

namespace {

using dynamics::SequenceData;
using dynamics::Split;

// Seed 002 eq. (1): the state x_t is the three module tips (mm, robot frame), the input τ_t the
// nine commanded chamber pressures (bar) sent at t and held until t + 1 — the recording's
// command columns, since row k's tips answer the commands of row k − 1.
void append(SequenceData& data, const envs::pneumatic::PneumaticDataset& recording, Split split) {
  const int64_t old_rows = data.rows(), rows = old_rows + recording.size();
  data.time.conservativeResize(rows);
  data.states.conservativeResize(rows, 9);
  data.inputs.conservativeResize(rows, 9);
  data.time.tail(recording.size()) = recording.time_s;
  data.states.bottomRows(recording.size()) = recording.tips_mm;
  data.inputs.bottomRows(recording.size()) = recording.commands_bar;
  data.split.insert(data.split.end(), recording.size(), split);
}

}  // namespace

int data_prepare_command(const Arguments& line) {
  require(line.positional.empty() && line.has("output") && (line.has("train") || line.has("test")),
          "expected --train FILE and/or --test FILE, and -o FILE", "tendril data prepare");
  SequenceData data;
  data.state_names = {"x1", "y1", "z1", "x2", "y2", "z2", "x3", "y3", "z3"};
  data.input_names = {"p1", "p2", "p3", "p4", "p5", "p6", "p7", "p8", "p9"};
  data.states.resize(0, 9);
  data.inputs.resize(0, 9);
  data.source = line.value("output", "");
  // A test recording restarts its clock at 0, so the reader's segments keep the two apart.
  for (const auto& [flag, split] : {std::pair{"train", Split::kTrain}, {"test", Split::kTest}}) {
    if (!line.has(flag)) continue;
    const auto recording = envs::pneumatic::read_pneumatic_dataset(line.value(flag, ""));
    append(data, recording, split);
    std::printf("%-5s %5d rows from %s\n", flag, recording.size(), line.value(flag, "").c_str());
  }
  dynamics::write_prepared_csv(data, line.value("output", ""));
  std::printf("wrote %s (time_s, x1 … z3 [mm], p1 … p9 [bar], split)\n",
              line.value("output", "").c_str());
  return 0;
}

}  // namespace tendril::apps
