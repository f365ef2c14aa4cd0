// `tendril plot`: figures (PNG, SVG, PDF) of runs, sweeps, CSV files and recorded episodes,
// drawn by matplotlib through the tendril_plot package (python/tendril_plot, docs/plotting.md).
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "commands.hpp"
#include "tendril/core/error.hpp"

namespace tendril::apps {

int plot_command(const Arguments& line) {
  // Debian's interpreter, which has python3-matplotlib (another python3 may come first on PATH).
  const char* python_override = std::getenv("TENDRIL_PYTHON");
  const std::string python = python_override != nullptr ? python_override : "/usr/bin/python3";
  // The plotting package's sources, after the build's tendril package (whose extension draws
  // the frames of `plot episode --video`).
  const char* package_override = std::getenv("TENDRIL_PLOT_PATH");
  std::string path = package_override != nullptr
                         ? package_override
                         : std::string(TENDRIL_PYTHON_BUILD_DIR) + ":" + TENDRIL_PYTHON_DIR;
  if (const char* existing = std::getenv("PYTHONPATH"); existing != nullptr && *existing != 0) {
    path += std::string(":") + existing;
  }
  ::setenv("PYTHONPATH", path.c_str(), 1);
  ::setenv("MPLBACKEND", "Agg", 1);  // files only, no display

  std::vector<std::string> words = {python, "-m", "tendril_plot"};
  words.insert(words.end(), line.raw.begin(), line.raw.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  ::execv(python.c_str(), argv.data());
  throw Error(std::string("cannot run the plotting package: ") + std::strerror(errno) +
                  " (scripts/setup installs python3-matplotlib)",
              python);
}

}  // namespace tendril::apps
