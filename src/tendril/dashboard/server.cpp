#include "tendril/dashboard/server.hpp"

#include <charconv>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>

#include "tendril/core/config.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/core/error.hpp"
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

}  // namespace

struct Server::Impl {
  ServerOptions options;
  ServedRoot root;
  httplib::Server http;
  int port = 0;

  explicit Impl(ServerOptions given) : options(std::move(given)), root(options.root) {
    http.set_default_headers(
        {{"X-Content-Type-Options", "nosniff"}, {"Referrer-Policy", "no-referrer"}});
    // Read-only: every method but GET (and HEAD, which httplib answers from GET) is refused.
    http.set_pre_routing_handler([](const httplib::Request& request, httplib::Response& response) {
      if (request.method == "GET" || request.method == "HEAD") {
        return httplib::Server::HandlerResponse::Unhandled;
      }
      response.set_header("Allow", "GET, HEAD");
      reply_error(response, 405, "read-only: only GET and HEAD are served");
      return httplib::Server::HandlerResponse::Handled;
    });
    route("/api/index", [this](const httplib::Request&, httplib::Response& r) { index(r); });
    route("/api/run", [this](const httplib::Request& q, httplib::Response& r) { run(q, r); });
    route("/api/csv", [this](const httplib::Request& q, httplib::Response& r) { csv(q, r); });
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
    const std::optional<fs::path> path = within.resolve(relative);
    if (!path) throw Refusal{403, "refused: the path leads outside the served directory"};
    if (!fs::exists(*path)) throw Refusal{404, "no such file: " + relative};
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
      for (const std::string& run : sweep.runs) json.value(run);
      json.end_array();
      json.key("summary").value(sweep.summary).key("figures").begin_array();
      for (const std::string& figure : sweep.figures) json.value(figure);
      json.end_array().end_object();
    }
    json.end_array().end_object();
    reply_json(response, 200, json.str());
  }

  void run(const httplib::Request& request, httplib::Response& response) const {
    const fs::path directory = parameter_path(request);
    if (!fs::is_directory(directory) || !is_run_directory(directory)) {
      throw Refusal{404, "not a run directory: " + request.get_param_value("path")};
    }
    JsonWriter json;
    json.begin_object().key("path").value(root.relative(directory));
    json.key("name").value(directory.filename().string());
    json.key("config");
    if (fs::is_regular_file(directory / "config.yaml")) {
      json.value(read_text(directory / "config.yaml"));
    } else {
      json.null();
    }
    json.key("files").begin_array();
    for (const char* name : {"progress.csv", "eval.csv", "evaluation.csv", "model.policy",
                             "best_model.policy", "model.tdm"}) {
      if (fs::is_regular_file(directory / name)) json.value(name);
    }
    json.end_array();
    std::optional<Config> config;
    try {
      if (fs::is_regular_file(directory / "config.yaml")) {
        config = Config::load_file(directory / "config.yaml");
      }
    } catch (const std::exception&) {  // the page shows the text as it is
    }
    write_state(json, read_run_state(directory, config ? &*config : nullptr, held_locks()));
    json.key("episodes").begin_array();
    for (const fs::path& file : episode_files(directory)) {
      json.begin_object().key("path").value(root.relative(file));
      json.key("name").value(file.filename().string());
      std::error_code error;
      json.key("bytes").value(static_cast<int64_t>(fs::file_size(file, error)));
      try {
        const PartialEpisode read = read_partial_episode(file);
        json.key("frames").value(static_cast<int64_t>(read.episode.frames.size()));
        json.key("complete").value(read.problem.empty());
        json.key("problem").value(read.problem);
        json.key("return");
        if (read.episode.summary) {
          json.value(read.episode.summary->episode_return);
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
    if (!fs::is_regular_file(file)) throw Refusal{404, "not a file"};
    if (file.extension() != ".csv") throw Refusal{400, "not a .csv file"};
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
    json.key("problems").begin_array();
    for (const std::string& problem : slice.problems) json.value(problem);
    json.end_array().end_object();
    reply_json(response, 200, json.str());
  }

  void episode(const httplib::Request& request, httplib::Response& response) const {
    const fs::path file = parameter_path(request);
    if (!fs::is_regular_file(file)) throw Refusal{404, "not a file"};
    const uint64_t max_frames = number_parameter(request, "max_frames", 2000);
    if (max_frames < 2 || max_frames > 100000) throw Refusal{400, "max_frames must be 2..100000"};
    reply_json(response, 200,
               episode_json(read_partial_episode(file), static_cast<int>(max_frames)));
  }

  void raw_file(const ServedRoot& within, const std::string& relative,
                httplib::Response& response) const {
    const fs::path file = resolve(within, relative);
    if (!fs::is_regular_file(file)) throw Refusal{404, "not a file: " + relative};
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
