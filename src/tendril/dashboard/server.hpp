#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

namespace tendril::dashboard {

struct ServerOptions {
  std::filesystem::path root;    // the directory served: runs and sweeps below it
  std::filesystem::path assets;  // the page: index.html and its bundled scripts
  std::string host = "127.0.0.1";
  int port = 8050;  // 0: any free port
  // What one /api/episode answer may build in memory, bytes (episode_json's max_bytes).
  std::size_t episode_memory = 64ull << 20;
};

// The dashboard's HTTP server (`tendril serve`, docs/dashboard.md): the page, and read-only JSON
// about the runs under the root —
//   GET /api/index                          runs and sweeps
//   GET /api/run?path=RUN                   a run's config, files and recorded episodes
//   GET /api/csv?path=FILE&offset=BYTES     rows of a CSV from a byte offset (live curves)
//   GET /api/episode?path=FILE&max_frames=N a recorded episode's frames
//   GET /files/PATH                         a file under the root as it is
// Every path is resolved through ServedRoot (nothing outside the root, symbolic links included),
// the ones the server derives itself (a run's config.yaml, its episodes/) too; any other method
// than GET and HEAD is refused, and so is a request whose Host header names another host than
// this server's (a page elsewhere that rebinds its own name to this machine), or that asks for
// more than one byte range. Damaged or half-written files are answered with what could be read
// and what is wrong; answers stay within a bounded multiple of what they read (CSV pages,
// episode frames chosen to fit episode_memory); no request can stop the server.
class Server {
 public:
  // Raises Error unless options.root is a directory.
  explicit Server(ServerOptions options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Binds the listening socket; returns the port. Raises Error when it cannot.
  int bind();
  // Serves until stop() is called (from another thread or a signal handler's thread).
  void run();
  void stop();
  bool running() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tendril::dashboard
