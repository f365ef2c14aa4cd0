// `tendril export`: a run's policy for other runtimes — a dependency-free C header (rl/export)
// and an ONNX model (the Python package's exporter, python/tendril/export.py).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/export/c_header.hpp"
#include "tendril/rl/policy.hpp"

namespace tendril::apps {

int export_command(const Arguments& line) {
  if (!line.has("c") && !line.has("onnx")) {
    throw UsageError("nothing to write: give --c FILE.h and/or --onnx FILE.onnx");
  }
  std::filesystem::path policy_file = line.positional.front();
  if (std::filesystem::is_directory(policy_file)) {
    policy_file /= line.has("best") ? "best_model.policy" : "model.policy";
  }
  if (line.has("c")) {
    const std::string out = line.value("c", "");
    rl::write_c_header(*rl::load_policy(policy_file), out, line.value("name", "policy"),
                       "from " + policy_file.string());
    std::printf("wrote %s\n", out.c_str());
    std::fflush(stdout);
  }
  if (!line.has("onnx")) return 0;
  // ONNX through the Python package (Debian's python3-onnx), as `tendril plot` runs matplotlib.
  const char* python_override = std::getenv("TENDRIL_PYTHON");
  const std::string python = python_override != nullptr ? python_override : "/usr/bin/python3";
  const char* package_override = std::getenv("TENDRIL_PLOT_PATH");
  std::string path = package_override != nullptr ? package_override : TENDRIL_PYTHON_BUILD_DIR;
  if (const char* existing = std::getenv("PYTHONPATH"); existing != nullptr && *existing != 0) {
    path += std::string(":") + existing;
  }
  ::setenv("PYTHONPATH", path.c_str(), 1);
  std::vector<std::string> words = {
      python, "-m", "tendril.export", policy_file.string(), "--onnx", line.value("onnx", "")};
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  ::execv(python.c_str(), argv.data());
  throw Error(std::string("cannot run the Python exporter: ") + std::strerror(errno), python);
}

}  // namespace tendril::apps
