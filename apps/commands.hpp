#pragma once

#include <string>
#include <vector>

namespace tendril::apps {

// Each command takes the arguments after its name and returns the process exit code.
int simulate_command(const std::vector<std::string>& args);
int list_envs_command(const std::vector<std::string>& args);
int train_command(const std::vector<std::string>& args);
int eval_command(const std::vector<std::string>& args);
int sweep_command(const std::vector<std::string>& args);
int metrics_command(const std::vector<std::string>& args);

}  // namespace tendril::apps
