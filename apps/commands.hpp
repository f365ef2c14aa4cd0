#pragma once

#include <string>
#include <vector>

namespace tendril::apps {

// Each command takes the arguments after its name and returns the process exit code.
int simulate_command(const std::vector<std::string>& args);
int list_envs_command(const std::vector<std::string>& args);
int collect_command(const std::vector<std::string>& args);
int train_command(const std::vector<std::string>& args);
int eval_command(const std::vector<std::string>& args);
int sweep_command(const std::vector<std::string>& args);
int summarize_command(const std::vector<std::string>& args);
int pneumatic_collect_command(const std::vector<std::string>& args);
int pneumatic_replay_command(const std::vector<std::string>& args);
int pneumatic_prepare_command(const std::vector<std::string>& args);
int adapt_command(const std::vector<std::string>& args);
int serve_command(const std::vector<std::string>& args);
int record_command(const std::vector<std::string>& args);
int plot_command(const std::vector<std::string>& args);
int dynamics_command(const std::vector<std::string>& args);
int rollout_command(const std::vector<std::string>& args);
int track_command(const std::vector<std::string>& args);
int safety_command(const std::vector<std::string>& args);
int export_command(const std::vector<std::string>& args);

// "SIGINT", "SIGTERM": how the interruption of a run is reported.
const char* signal_name(int signal);

}  // namespace tendril::apps
