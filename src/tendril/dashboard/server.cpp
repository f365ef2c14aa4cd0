#include "tendril/dashboard/server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/run_curves.hpp"
#include "tendril/dashboard/csv_slice.hpp"
#include "tendril/dashboard/episode_json.hpp"
#include "tendril/dashboard/json_writer.hpp"
#include "tendril/dashboard/run_index.hpp"
#include "tendril/dashboard/run_state.hpp"
#include "tendril/dashboard/served_root.hpp"

// After Eigen (through the episode reader): httplib.h brings in <resolv.h>, whose `_res` macro
// would rewrite a parameter name inside Eigen's headers.
// clang-format off
#include <httplib.h>
// clang-format on

namespace tendril::dashboard {

namespace fs = std::filesystem;

namespace {

constexpr const char* kJson = "application/json";
constexpr uint64_t kMaxFileBytes = 256ull << 20;
// Worker threads and how long each waits for a silent client: idle connections (a browser's
// kept-alive ones, or someone's held open on purpose) each hold a worker until then, so a few
// dozen of them must not delay everyone else by more than a moment.
constexpr std::size_t kWorkerThreads = 32;
constexpr time_t kReadTimeoutSeconds = 2;
constexpr time_t kKeepAliveSeconds = 2;

// A request that cannot be answered: its status and why.
struct Refusal {
  int status;
  std::string message;
};

void reply_json(httplib::Response& response, int status, const std::string& body) {
  response.status = status;
  response.set_header("Cache-Control", "no-store");
  response.set_content(body, kJson);
}

void reply_error(httplib::Response& response, int status, const std::string& message) {
  JsonWriter json;
  json.begin_object().key("error").value(message).end_object();
  reply_json(response, status, json.str());
}

std::string content_type(const fs::path& file) {
  static const std::map<std::string, std::string> types = {
      {".html", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".csv", "text/csv; charset=utf-8"},
      {".yaml", "text/plain; charset=utf-8"},
      {".txt", "text/plain; charset=utf-8"},
      {".md", "text/plain; charset=utf-8"},
      {".png", "image/png"},
      {".svg", "image/svg+xml"},
      {".pdf", "application/pdf"},
      {".map", "application/json"}};
  const auto found = types.find(file.extension().string());
  return found != types.end() ? found->second : "application/octet-stream";
}

std::string read_text(const fs::path& file) {
  std::error_code error;
  const uint64_t size = fs::file_size(file, error);
  if (error) throw Refusal{404, "cannot read " + file.filename().string()};
  if (size > kMaxFileBytes) throw Refusal{413, "too large to serve"};
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Refusal{404, "cannot read " + file.filename().string()};
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_state(JsonWriter& json, const RunState& state) {
  json.key("kind").value(state.kind).key("status").value(state.status);
  json.key("pid").value(state.pid).key("steps").value(state.steps).key("total").value(state.total);
  json.key("last_return").value(state.last_return).key("last_eval").value(state.last_eval);
  json.key("last_loss").value(state.last_loss).key("checkpoint").value(state.checkpoint);
}

void write_run(JsonWriter& json, const RunEntry& run) {
  json.begin_object();
  json.key("path").value(run.path).key("name").value(run.name);
  json.key("env_id").value(run.env_id).key("algorithm").value(run.algorithm);
  json.key("has_progress").value(run.has_progress).key("has_eval").value(run.has_eval);
  json.key("episodes").value(run.episodes).key("modified").value(run.modified);
  json.key("problem").value(run.problem);
  write_state(json, run.state);
  json.end_object();
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The host name of a Host header ("name:port", "[v6]:port", "name"), lower case, brackets kept.
std::string host_name(const std::string& header) {
  std::string host = header;
  if (!host.empty() && host.front() == '[') {
    const std::size_t close = host.find(']');
    host = close == std::string::npos ? host : host.substr(0, close + 1);
  } else if (const std::size_t colon = host.rfind(':'); colon != std::string::npos) {
    host = host.substr(0, colon);
  }
  if (!host.empty() && host.back() == '.') host.pop_back();
  return lower(host);
}

bool is_ip_literal(const std::string& host) {
  unsigned char address[sizeof(in6_addr)];
  if (inet_pton(AF_INET, host.c_str(), address) == 1) return true;
  return host.size() > 2 && host.front() == '[' && host.back() == ']' &&
         inet_pton(AF_INET6, host.substr(1, host.size() - 2).c_str(), address) == 1;
}

bool is_wildcard(const std::string& host) {
  return host.empty() || host == "0.0.0.0" || host == "::" || host == "[::]";
}

// Binds like httplib's default, but without SO_REUSEPORT: with it a second server on the same
// port would start too, and the kernel would spread connections over both.
void exclusive_socket_options(socket_t socket) {
  int yes = 1;
  setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
}

}  // namespace

struct Server::Impl {
  ServerOptions options;
  ServedRoot root;
  httplib::Server http;
  int port = 0;

  explicit Impl(ServerOptions given) : options(std::move(given)), root(options.root) {
    http.set_default_headers(
        {{"X-Content-Type-Options", "nosniff"}, {"Referrer-Policy", "no-referrer"}});
    http.set_socket_options(exclusive_socket_options);
    // An answer's header and body leave in separate writes: without this, Nagle's algorithm
    // holds the body until the client's delayed acknowledgement (~40 ms per request).
    http.set_tcp_nodelay(true);
    http.new_task_queue = [] { return new httplib::ThreadPool(kWorkerThreads); };
    http.set_read_timeout(kReadTimeoutSeconds, 0);
    http.set_keep_alive_timeout(kKeepAliveSeconds);
    http.set_pre_routing_handler([this](const httplib::Request& request,
                                        httplib::Response& response) {
      // Read-only: every method but GET (and HEAD, which httplib answers from GET) is refused.
      if (request.method != "GET" && request.method != "HEAD") {
        response.set_header("Allow", "GET, HEAD");
        reply_error(response, 405, "read-only: only GET and HEAD are served");
        return httplib::Server::HandlerResponse::Handled;
      }
      // A page elsewhere that makes its own name resolve to this machine (DNS rebinding) sends
      // its own name as Host: only this server's names are answered.
      for (std::size_t i = 0; i < request.get_header_value_count("Host"); ++i) {
        const std::string host = host_name(request.get_header_value("Host", i));
        if (!allowed_host(host)) {
          reply_error(response, 403,
                      "refused: '" + host + "' is not an address of this dashboard (open it as " +
                          "http://127.0.0.1:" + std::to_string(port) + "/)");
          return httplib::Server::HandlerResponse::Handled;
        }
      }
      // httplib builds a multi-range answer whole in memory (ranges × file size): one range per
      // request is all a browser asks for.
      if (request.ranges.size() > 1) {
        reply_error(response, 416, "one byte range per request");
        return httplib::Server::HandlerResponse::Handled;
      }
      return httplib::Server::HandlerResponse::Unhandled;
    });
    route("/api/index", [this](const httplib::Request&, httplib::Response& r) { index(r); });
    route("/api/run", [this](const httplib::Request& q, httplib::Response& r) { run(q, r); });
    route("/api/csv", [this](const httplib::Request& q, httplib::Response& r) { csv(q, r); });
    route("/api/curves", [this](const httplib::Request& q, httplib::Response& r) { curves(q, r); });
    route("/api/episode",
          [this](const httplib::Request& q, httplib::Response& r) { episode(q, r); });
    route(R"(/files/(.*))", [this](const httplib::Request& q, httplib::Response& r) {
      raw_file(root, q.matches[1].str(), r);
    });
    route(R"(/assets/(.*))", [this](const httplib::Request& q, httplib::Response& r) {
      page_file(q.matches[1].str(), r);
    });
    route("/",
          [this](const httplib::Request&, httplib::Response& r) { page_file("index.html", r); });
    http.set_error_handler([](const httplib::Request&, httplib::Response& response) {
      if (response.body.empty()) reply_error(response, response.status, "not found");
    });
  }

  // Loopback names and addresses, the host the server was told to bind, and — when it listens on
  // every interface — any address literal and this machine's name.
  bool allowed_host(const std::string& host) const {
    static const std::vector<std::string> loopback = {"localhost", "127.0.0.1", "[::1]"};
    if (std::find(loopback.begin(), loopback.end(), host) != loopback.end()) return true;
    if (host.size() > 10 && host.compare(host.size() - 10, 10, ".localhost") == 0) return true;
    if (host.rfind("127.", 0) == 0 && is_ip_literal(host)) return true;
    const std::string configured = lower(options.host);
    if (host == configured || host == "[" + configured + "]") return true;
    if (!is_wildcard(configured)) return false;
    if (is_ip_literal(host)) return true;
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return false;
    const std::string machine = lower(name);
    return host == machine || host.rfind(machine + ".", 0) == 0;
  }

  // Registers a GET handler whose refusals and errors become JSON answers.
  template <typename Handler>
  void route(const std::string& pattern, Handler handler) {
    http.Get(pattern, [handler](const httplib::Request& request, httplib::Response& response) {
      try {
        handler(request, response);
      } catch (const Refusal& refusal) {
        reply_error(response, refusal.status, refusal.message);
      } catch (const Error& e) {
        reply_error(response, 422, e.what());
      } catch (const std::exception& e) {
        reply_error(response, 500, e.what());
      }
    });
  }

  // The file a request's `path` parameter names inside the root.
  fs::path resolve(const ServedRoot& within, const std::string& relative) const {
    if (!ServedRoot::nameable(relative)) throw Refusal{404, "no such file (the name is too long)"};
    const std::optional<fs::path> path = within.resolve(relative);
    if (!path) throw Refusal{403, "refused: the path leads outside the served directory"};
    std::error_code error;
    if (!fs::exists(*path, error)) throw Refusal{404, "no such file: " + relative};
    return *path;
  }

  fs::path parameter_path(const httplib::Request& request) const {
    if (!request.has_param("path")) throw Refusal{400, "missing parameter 'path'"};
    return resolve(root, request.get_param_value("path"));
  }

  static uint64_t number_parameter(const httplib::Request& request, const char* name,
                                   uint64_t fallback) {
    if (!request.has_param(name)) return fallback;
    const std::string text = request.get_param_value(name);
    uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
      throw Refusal{400, std::string("parameter '") + name + "' is not a whole number"};
    }
    return value;
  }

  void index(httplib::Response& response) const {
    const RunIndex found = index_runs(root);
    JsonWriter json;
    json.begin_object().key("root").value(root.path().filename().string());
    json.key("runs").begin_array();
    for (const RunEntry& run : found.runs) write_run(json, run);
    json.end_array().key("sweeps").begin_array();
    for (const SweepEntry& sweep : found.sweeps) {
      json.begin_object().key("path").value(sweep.path).key("name").value(sweep.name);
      json.key("runs").begin_array();
      std::vector<fs::path> runs;
      for (const std::string& run : sweep.runs) {
        json.value(run);
        runs.push_back(root.path() / run);
      }
      json.end_array().key("groups").value(static_cast<int64_t>(group_by_seed(runs).size()));
      json.key("summary").value(sweep.summary).key("figures").begin_array();
      for (const std::string& figure : sweep.figures) json.value(figure);
      json.end_array().end_object();
    }
    json.end_array().end_object();
    reply_json(response, 200, json.str());
  }

  void run(const httplib::Request& request, httplib::Response& response) const {
    const fs::path directory = parameter_path(request);
    std::error_code error;
    if (!fs::is_directory(directory, error) || !is_run_directory(root, directory)) {
      throw Refusal{404, "not a run directory: " + request.get_param_value("path")};
    }
    JsonWriter json;
    json.begin_object().key("path").value(root.relative(directory));
    json.key("name").value(directory.filename().string());
    json.key("config");
    if (const std::optional<fs::path> config = root.served_file(directory / "config.yaml")) {
      json.value(read_text(*config));
    } else {
      json.null();
    }
    json.key("files").begin_array();
    for (const char* name : {"progress.csv", "eval.csv", "evaluation.csv", "model.policy",
                             "best_model.policy", "model.tdm"}) {
      if (root.served_file(directory / name)) json.value(name);
    }
    json.end_array();
    std::optional<Config> config;
    try {
      if (const std::optional<fs::path> file = root.served_file(directory / "config.yaml")) {
        config = Config::load_file(*file);
      }
    } catch (const std::exception&) {  // the page shows the text as it is
    }
    write_state(json, read_run_state(root, directory, config ? &*config : nullptr, held_locks()));
    json.key("episodes").begin_array();
    for (const fs::path& file : episode_files(root, directory)) {
      json.begin_object().key("path").value(root.relative(file));
      json.key("name").value(file.filename().string());
      const uint64_t bytes = fs::file_size(file, error);
      json.key("bytes").value(static_cast<int64_t>(error ? 0 : bytes));
      try {
        if (!error && bytes > kMaxFileBytes) throw Error("too large to read");
        // The frames are counted, not built: listing costs memory per frame, not per scene.
        const EpisodeOutline read = outline_episode(file);
        json.key("frames").value(read.frames());
        json.key("complete").value(read.problem.empty());
        json.key("problem").value(read.problem);
        json.key("return");
        if (read.summary) {
          json.value(read.summary->episode_return);
        } else {
          json.null();
        }
      } catch (const Error& e) {
        json.key("frames").value(0).key("complete").value(false);
        json.key("problem").value(e.what_wrong()).key("return").null();
      }
      json.end_object();
    }
    json.end_array().end_object();
    reply_json(response, 200, json.str());
  }

  void csv(const httplib::Request& request, httplib::Response& response) const {
    const fs::path file = parameter_path(request);
    std::error_code error;
    if (!fs::is_regular_file(file, error)) throw Refusal{404, "not a file"};
    if (file.extension() != ".csv") throw Refusal{400, "not a .csv file"};
    // A bounded number of lines and problems per answer (CsvSliceLimits): the page asks again
    // from next_offset while `more`.
    const CsvSlice slice = read_csv_slice(file, number_parameter(request, "offset", 0));
    JsonWriter json;
    json.begin_object().key("columns").begin_array();
    for (const std::string& column : slice.columns) json.value(column);
    json.end_array().key("rows").begin_array();
    for (const auto& row : slice.rows) json.numbers(row, 10);
    json.end_array();
    json.key("first_line").value(slice.first_line);
    json.key("next_offset").value(slice.next_offset);
    json.key("size").value(slice.size);
    json.key("restarted").value(slice.restarted);
    json.key("partial_line").value(slice.partial_line);
    json.key("more").value(slice.more);
    json.key("problems").begin_array();
    for (const std::string& problem : slice.problems) json.value(problem);
    json.end_array();
    json.key("problem_count").value(slice.problem_count);
    json.end_object();
    reply_json(response, 200, json.str());
  }

  // One metric of several runs, the runs grouped by seed and each group's mean, spread and run
  // count at every point (core/run_curves, as `tendril plot curves` and the sweep summaries
  // compute them), over the span any of its runs covers: runs still training shorten nothing.
  // `runs` holds the run directories separated by '|'; `metric` is "eval", "eval:<column>" or
  // a progress.csv column.
  void curves(const httplib::Request& request, httplib::Response& response) const {
    if (!request.has_param("runs")) throw Refusal{400, "missing parameter 'runs'"};
    if (!request.has_param("metric")) throw Refusal{400, "missing parameter 'metric'"};
    const std::string metric = request.get_param_value("metric");
    const uint64_t points = number_parameter(request, "points", 200);
    if (points < 1 || points > 10000) throw Refusal{400, "points must be 1..10000"};
    std::vector<fs::path> runs;
    const std::string listed = request.get_param_value("runs");
    for (std::size_t start = 0; start <= listed.size();) {
      const std::size_t end = std::min(listed.find('|', start), listed.size());
      const std::string relative = listed.substr(start, end - start);
      start = end + 1;
      if (relative.empty()) continue;
      const fs::path directory = resolve(root, relative);
      std::error_code error;
      if (!fs::is_directory(directory, error) || !is_run_directory(root, directory)) {
        throw Refusal{404, "not a run directory: " + relative};
      }
      runs.push_back(directory);
    }
    if (runs.empty()) throw Refusal{400, "no runs in parameter 'runs'"};
    JsonWriter json;
    json.begin_object().key("metric").value(metric).key("groups").begin_array();
    for (const RunGroup& group : group_by_seed(runs)) {
      std::vector<Curve> curves;
      std::vector<std::string> problems;
      json.begin_object().key("name").value(group.name).key("runs").begin_array();
      for (const int i : group.members) {
        json.value(root.relative(runs[i]));
        // A run that has not written the file or column yet adds no curve, and says why.
        try {
          curves.push_back(read_run_curve(runs[i], metric));
        } catch (const Error& e) {
          problems.push_back(root.relative(runs[i]) + "/" +
                             fs::path(e.where()).filename().string() + ": " + e.what_wrong());
        }
      }
      json.end_array().key("problems").begin_array();
      for (const std::string& problem : problems) json.value(problem);
      json.end_array();
      const CurveStats stats = aggregate_curves(curves, static_cast<int>(points), CurveSpan::kAny);
      json.key("curves").value(stats.curves);
      json.key("x").numbers(stats.x, 10).key("mean").numbers(stats.mean, 10);
      json.key("std").numbers(stats.std, 10).key("min").numbers(stats.min, 10);
      json.key("max").numbers(stats.max, 10);
      json.key("count").begin_array();
      for (const int n : stats.count) json.value(n);
      json.end_array().end_object();
    }
    json.end_array().end_object();
    reply_json(response, 200, json.str());
  }

  void episode(const httplib::Request& request, httplib::Response& response) const {
    const fs::path file = parameter_path(request);
    std::error_code error;
    if (!fs::is_regular_file(file, error)) throw Refusal{404, "not a file"};
    const uint64_t max_frames = number_parameter(request, "max_frames", 2000);
    if (max_frames < 2 || max_frames > 100000) throw Refusal{400, "max_frames must be 2..100000"};
    if (fs::file_size(file, error) > kMaxFileBytes) throw Refusal{413, "too large to serve"};
    reply_json(response, 200,
               episode_json(file, static_cast<int>(max_frames), options.episode_memory));
  }

  void raw_file(const ServedRoot& within, const std::string& relative,
                httplib::Response& response) const {
    const fs::path file = resolve(within, relative);
    std::error_code error;
    if (!fs::is_regular_file(file, error)) throw Refusal{404, "not a file: " + relative};
    response.set_content(read_text(file), content_type(file));
  }

  void page_file(const std::string& relative, httplib::Response& response) const {
    if (!fs::is_regular_file(options.assets / "index.html")) {
      response.status = 503;
      response.set_content(
          "<!doctype html><title>tendril</title><p>The dashboard's page was not built: "
          "run scripts/setup (installs its npm packages) and build again. The JSON API under "
          "/api/ works without it.</p>",
          "text/html; charset=utf-8");
      return;
    }
    raw_file(ServedRoot(options.assets), relative, response);
    response.set_header("Content-Security-Policy",
                        "default-src 'self'; style-src 'self' 'unsafe-inline'; "
                        "img-src 'self' data: blob:");
  }
};

Server::Server(ServerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

Server::~Server() { stop(); }

int Server::bind() {
  Impl& impl = *impl_;
  const std::string where = impl.options.host + ":" + std::to_string(impl.options.port);
  if (impl.options.port == 0) {
    impl.port = impl.http.bind_to_any_port(impl.options.host);
    require(impl.port > 0, "cannot listen", where);
  } else {
    require(impl.http.bind_to_port(impl.options.host, impl.options.port),
            "cannot listen (in use, or not an address of this machine)", where);
    impl.port = impl.options.port;
  }
  return impl.port;
}

void Server::run() { impl_->http.listen_after_bind(); }

bool Server::running() const { return impl_->http.is_running(); }

void Server::stop() {
  if (impl_ && impl_->http.is_running()) impl_->http.stop();
}

}  // namespace tendril::dashboard
