// `tendril serve`: the dashboard of the runs under a directory, in a browser.
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/arguments.hpp"
#include "commands.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dashboard/server.hpp"

namespace tendril::apps {

namespace {

bool is_loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

}  // namespace

int serve_command(const Arguments& line) {
  require(line.positional.size() == 1, "expected one directory to serve", "command line");
  dashboard::ServerOptions options;
  options.root = line.positional.front();
  options.assets = line.value("assets", TENDRIL_DASHBOARD_PAGE_DIR);
  options.host = line.value("host", "127.0.0.1");
  options.port = static_cast<int>(line.integer("port", 8050, 0, 65535));

  dashboard::Server server(options);
  const int port = server.bind();
  const std::string host =
      options.host.find(':') != std::string::npos ? "[" + options.host + "]" : options.host;
  std::printf("dashboard of %s (read-only): http://%s:%d/\n",
              std::filesystem::absolute(options.root).lexically_normal().c_str(), host.c_str(),
              port);
  if (!is_loopback(options.host)) {
    std::printf("warning: listening on %s: whoever reaches this machine can read the runs\n",
                options.host.c_str());
  }
  if (!std::filesystem::is_regular_file(options.assets / "index.html")) {
    std::printf("warning: the page is not built (%s); only the JSON API under /api/ answers\n",
                options.assets.c_str());
  }
  std::printf("Ctrl-C stops it.\n");
  std::fflush(stdout);
  server.run();
  return 0;
}

}  // namespace tendril::apps
