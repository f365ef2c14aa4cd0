#include "tendril/dashboard/server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <thread>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/episode_writer.hpp"

// After Eigen: httplib.h brings in <resolv.h>, whose `_res` macro breaks Eigen's headers.
// clang-format off
#include <httplib.h>
// clang-format on

namespace tendril::dashboard {
namespace {

namespace fs = std::filesystem;

// A served directory with one run (config, curves, a finished and a half-written episode),
// a page directory, and a secret file beside them that must never be served.
class ServerTest : public testing::ScratchDirectoryTest {
 protected:
  ServerTest() : ScratchDirectoryTest("dashboard_server") {}

  void SetUp() override {
    ScratchDirectoryTest::SetUp();
    const fs::path run = directory_ / "root" / "runs" / "ppo_seed0";
    fs::create_directories(run / "episodes");
    std::ofstream(run / "config.yaml") << "algorithm: ppo\nenv: {id: Test-v0}\n";
    std::ofstream(run / "progress.csv") << "time/total_timesteps,rollout/ep_rew_mean\n"
                                        << "100,-5\n200,-4\n300,-3";  // last line unfinished
    std::ofstream(run / "eval.csv") << "timesteps,mean_return\n100,-6\nbroken\n";
    write_episode(run / "episodes" / "episode_0000.tep", 5, true);
    write_episode(run / "episodes" / "episode_0001.tep", 3, false);
    std::ofstream(run / "episodes" / "garbage.tep") << "not an episode";
    fs::create_directories(directory_ / "page");
    std::ofstream(directory_ / "page" / "index.html") << "<!doctype html><title>page</title>";
    std::ofstream(directory_ / "page" / "app.js") << "console.log(1);";
    std::ofstream(directory_ / "secret.txt") << "outside";
    fs::create_symlink(directory_ / "secret.txt", run / "leak.csv");
    fs::create_directory_symlink(directory_, directory_ / "root" / "up");

    // Runs whose config.yaml or episodes/ are links out of the root, and a run directory and an
    // episode file outside it.
    const fs::path outside = directory_ / "outside" / "outrun";
    fs::create_directories(outside / "episodes");
    std::ofstream(outside / "config.yaml") << "algorithm: TOP-SECRET-OUTSIDE\n";
    std::ofstream(outside / "progress.csv") << "MARKERCOL,b\n1,2\n";
    write_episode(outside / "episodes" / "private.tep", 4, true, "outside-episode-marker");
    fs::create_directories(directory_ / "root" / "runs" / "linked_config");
    fs::create_symlink(outside / "config.yaml",
                       directory_ / "root" / "runs" / "linked_config" / "config.yaml");
    fs::create_directories(directory_ / "root" / "runs" / "linked_episodes");
    std::ofstream(directory_ / "root" / "runs" / "linked_episodes" / "config.yaml")
        << "algorithm: sac\n";
    fs::create_directory_symlink(outside / "episodes",
                                 directory_ / "root" / "runs" / "linked_episodes" / "episodes");
    fs::create_symlink(outside / "episodes" / "private.tep", run / "episodes" / "linked.tep");
    fs::create_directory_symlink(directory_ / "outside", directory_ / "root" / "link_dir");
    fs::create_directory_symlink("/etc", directory_ / "root" / "etc_link");
    fs::create_symlink("loop", directory_ / "root" / "loop");

    server_ = std::make_unique<Server>(
        ServerOptions{directory_ / "root", directory_ / "page", "127.0.0.1", 0, kEpisodeMemory});
    port_ = server_->bind();
    thread_ = std::thread([this] { server_->run(); });
    for (int i = 0; i < 500 && !server_->running(); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_connection_timeout(2);
    client_->set_read_timeout(5);
  }

  void TearDown() override {
    server_->stop();
    thread_.join();
    ScratchDirectoryTest::TearDown();
  }

  static constexpr std::size_t kEpisodeMemory = 4u << 20;

  static void write_episode(const fs::path& file, int frames, bool finish,
                            const std::string& env = "Test-v0") {
    EpisodeWriter writer(file, {{"env", env}}, 1);
    for (int k = 0; k < frames; ++k) {
      EpisodeFrame frame;
      frame.step = k;
      frame.reward = k > 0 ? 1.0 : 0.0;
      frame.scene.time = 0.1 * k;
      Eigen::Matrix3Xd centreline(3, 3);
      centreline << 0, 0, 0.01 * k, 0, 0, 0, 0, 0.5, 1.0;
      frame.scene.rods.push_back({"arm", centreline, Eigen::VectorXd::Constant(2, 0.02)});
      frame.scene.spheres.push_back({"target", Eigen::Vector3d(0.1 * k, 0, 1), 0.05});
      writer.write(frame);
    }
    if (finish) writer.finish();
  }

  // GET of a raw request target, exactly as given (no client-side normalization).
  httplib::Result get(const std::string& target) { return client_->Get(target); }

  // A connected socket to the server (-1 when it cannot connect).
  int connect_socket() const {
    const int socket = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port_));
    inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
    if (::connect(socket, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
      ::close(socket);
      return -1;
    }
    return socket;
  }

  struct RawAnswer {
    int status = 0;  // 0: no answer
    std::string head, body;
  };

  // The request line and headers sent byte for byte as given (the target unencoded), read to
  // the end of the connection.
  RawAnswer raw_get(const std::string& target, const std::string& headers = "Host: 127.0.0.1\r\n") {
    RawAnswer answer;
    const int socket = connect_socket();
    if (socket < 0) return answer;
    timeval timeout{10, 0};
    setsockopt(socket, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    int yes = 1;
    setsockopt(socket, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    const std::string request =
        "GET " + target + " HTTP/1.1\r\n" + headers + "Connection: close\r\n\r\n";
    if (::send(socket, request.data(), request.size(), MSG_NOSIGNAL) < 0) {
      ::close(socket);
      return answer;
    }
    std::string bytes;
    char buffer[65536];
    for (ssize_t got; (got = ::recv(socket, buffer, sizeof buffer, 0)) > 0;) {
      bytes.append(buffer, static_cast<std::size_t>(got));
    }
    ::close(socket);
    const std::size_t split = bytes.find("\r\n\r\n");
    if (bytes.rfind("HTTP/1.1 ", 0) != 0 || split == std::string::npos) return answer;
    answer.status = std::stoi(bytes.substr(9, 3));
    answer.head = bytes.substr(0, split);
    answer.body = bytes.substr(split + 4);
    return answer;
  }

  std::unique_ptr<Server> server_;
  int port_ = 0;
  std::thread thread_;
  std::unique_ptr<httplib::Client> client_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_F(ServerTest, ListsRunsAndServesTheirFiles) {
  auto index = get("/api/index");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->status, 200);
  EXPECT_TRUE(contains(index->body, R"("path":"runs/ppo_seed0")")) << index->body;
  EXPECT_TRUE(contains(index->body, R"("algorithm":"ppo")"));
  EXPECT_TRUE(contains(index->body, R"("episodes":3)"));

  auto run = get("/api/run?path=runs/ppo_seed0");
  ASSERT_TRUE(run);
  EXPECT_EQ(run->status, 200);
  EXPECT_TRUE(contains(run->body, R"("config":"algorithm: ppo\nenv: {id: Test-v0}\n")"));
  EXPECT_TRUE(contains(run->body, R"("name":"episode_0000.tep","bytes":)"));
  EXPECT_TRUE(contains(run->body, R"("frames":5,"complete":true,"problem":"","return":4)"));
  EXPECT_TRUE(contains(run->body, R"("frames":3,"complete":false,"problem":"no end record)"));
  EXPECT_TRUE(contains(run->body, R"("frames":0,"complete":false,"problem":"not an episode file)"));

  auto config = get("/files/runs/ppo_seed0/config.yaml");
  ASSERT_TRUE(config);
  EXPECT_EQ(config->status, 200);
  EXPECT_EQ(config->body, "algorithm: ppo\nenv: {id: Test-v0}\n");
  EXPECT_EQ(config->get_header_value("Content-Type"), "text/plain; charset=utf-8");

  auto page = get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_EQ(page->body, "<!doctype html><title>page</title>");
  EXPECT_TRUE(contains(page->get_header_value("Content-Security-Policy"), "default-src 'self'"));
  auto script = get("/assets/app.js");
  ASSERT_TRUE(script);
  EXPECT_EQ(script->body, "console.log(1);");
}

TEST_F(ServerTest, CsvRowsComeInSlicesAndMalformedLinesAreReported) {
  auto first = get("/api/csv?path=runs/ppo_seed0/progress.csv");
  ASSERT_TRUE(first);
  EXPECT_EQ(first->status, 200);
  EXPECT_TRUE(contains(first->body,
                       R"("columns":["time/total_timesteps","rollout/ep_rew_mean"],)"
                       R"("rows":[[100,-5],[200,-4]],"first_line":2,"next_offset":55,)"))
      << first->body;
  EXPECT_TRUE(contains(first->body, R"("partial_line":true)"));
  auto next = get("/api/csv?path=runs/ppo_seed0/progress.csv&offset=55");
  ASSERT_TRUE(next);
  EXPECT_TRUE(contains(next->body, R"("rows":[],)")) << next->body;

  auto eval = get("/api/csv?path=runs/ppo_seed0/eval.csv");
  ASSERT_TRUE(eval);
  EXPECT_EQ(eval->status, 200);
  EXPECT_TRUE(contains(eval->body, R"("problems":["line 3: 1 cells, the header has 2"])"))
      << eval->body;

  auto bad_offset = get("/api/csv?path=runs/ppo_seed0/progress.csv&offset=-3");
  ASSERT_TRUE(bad_offset);
  EXPECT_EQ(bad_offset->status, 400);
  auto not_csv = get("/api/csv?path=runs/ppo_seed0/config.yaml");
  ASSERT_TRUE(not_csv);
  EXPECT_EQ(not_csv->status, 400);
}

// Runs grouped by seed with each group's statistics at every point, over the span any of its
// runs covers (core/run_curves): ppo_seed0 has rows at 100 and 200 (its line at 300 is still
// being written), ppo_seed1 at 100 and 400; on the grid 100, 250, 400 the first point averages
// both seeds and the others only ppo_seed1, whose value at 250 is interpolated.
TEST_F(ServerTest, CurvesOfRunsComeGroupedBySeed) {
  const fs::path runs = directory_ / "root" / "runs";
  fs::create_directories(runs / "ppo_seed1");
  std::ofstream(runs / "ppo_seed1" / "config.yaml") << "algorithm: ppo\n";
  std::ofstream(runs / "ppo_seed1" / "progress.csv")
      << "time/total_timesteps,rollout/ep_rew_mean\n100,-7\n400,-1\n";
  fs::create_directories(runs / "sac_seed0");
  std::ofstream(runs / "sac_seed0" / "config.yaml") << "algorithm: sac\n";

  auto answer =
      get("/api/curves?runs=runs/ppo_seed0|runs/ppo_seed1|runs/sac_seed0"
          "&metric=rollout/ep_rew_mean&points=3");
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->status, 200) << answer->body;
  EXPECT_EQ(answer->body,
            R"({"metric":"rollout/ep_rew_mean","groups":[)"
            R"({"name":"ppo","runs":["runs/ppo_seed0","runs/ppo_seed1"],"problems":[],)"
            R"("curves":2,"x":[100,250,400],"mean":[-6,-4,-1],"std":[1,0,0],"min":[-7,-4,-1],)"
            R"("max":[-5,-4,-1],"count":[2,1,1]},)"
            R"({"name":"sac","runs":["runs/sac_seed0"],)"
            R"("problems":["runs/sac_seed0/progress.csv: no such file"],)"
            R"("curves":0,"x":[],"mean":[],"std":[],"min":[],"max":[],"count":[]}]})");

  // The index counts a directory's groups the same way: linked_episodes, ppo (two seeds), sac.
  auto index = get("/api/index");
  ASSERT_TRUE(index);
  EXPECT_TRUE(contains(index->body,
                       R"("runs":["runs/linked_episodes","runs/ppo_seed0","runs/ppo_seed1",)"
                       R"("runs/sac_seed0"],"groups":3,)"))
      << index->body;

  auto evaluation = get("/api/curves?runs=runs/ppo_seed0&metric=eval");
  ASSERT_TRUE(evaluation);
  EXPECT_TRUE(contains(evaluation->body, R"("x":[100],"mean":[-6],)")) << evaluation->body;
  auto no_column = get("/api/curves?runs=runs/ppo_seed1&metric=train/loss");
  ASSERT_TRUE(no_column);
  EXPECT_TRUE(contains(no_column->body,
                       "runs/ppo_seed1/progress.csv: has no column 'train/loss' (it has: "
                       "rollout/ep_rew_mean, time/total_timesteps)"))
      << no_column->body;

  for (const auto& [target, status] : std::vector<std::pair<std::string, int>>{
           {"/api/curves?metric=eval", 400},
           {"/api/curves?runs=runs/ppo_seed0", 400},
           {"/api/curves?runs=|&metric=eval", 400},
           {"/api/curves?runs=runs/ppo_seed0&metric=eval&points=0", 400},
           {"/api/curves?runs=runs/none&metric=eval", 404},
           {"/api/curves?runs=runs&metric=eval", 404},
           {"/api/curves?runs=runs/ppo_seed0|../outside/outrun&metric=eval", 403}}) {
    auto refused = get(target);
    ASSERT_TRUE(refused) << target;
    EXPECT_EQ(refused->status, status) << target << " " << refused->body;
  }
}

TEST_F(ServerTest, EpisodesComeWithTheirFramesOrWhatIsWrong) {
  auto whole = get("/api/episode?path=runs/ppo_seed0/episodes/episode_0000.tep");
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->status, 200);
  EXPECT_TRUE(contains(whole->body, R"("metadata":{"env":"Test-v0"},"complete":true)"))
      << whole->body.substr(0, 300);
  EXPECT_TRUE(contains(whole->body, R"("frame_count":5,"stride":1)"));
  EXPECT_TRUE(contains(whole->body, R"({"role":"target","centre":[0.2,0,1],"radius":0.05})"));

  auto sampled = get("/api/episode?path=runs/ppo_seed0/episodes/episode_0000.tep&max_frames=3");
  ASSERT_TRUE(sampled);
  EXPECT_TRUE(contains(sampled->body, R"("frame_count":5,"stride":3)")) << sampled->body;
  EXPECT_TRUE(contains(sampled->body, R"("step":0,)"));
  EXPECT_TRUE(contains(sampled->body, R"("step":3,)"));
  EXPECT_TRUE(contains(sampled->body, R"("step":4,)"));  // the last frame, always
  EXPECT_FALSE(contains(sampled->body, R"("step":1,)"));

  auto unfinished = get("/api/episode?path=runs/ppo_seed0/episodes/episode_0001.tep");
  ASSERT_TRUE(unfinished);
  EXPECT_EQ(unfinished->status, 200);
  EXPECT_TRUE(contains(unfinished->body, R"("complete":false,"truncated":true,"problem":"no end)"));
  EXPECT_TRUE(contains(unfinished->body, R"("frame_count":3)"));

  auto garbage = get("/api/episode?path=runs/ppo_seed0/episodes/garbage.tep");
  ASSERT_TRUE(garbage);
  EXPECT_EQ(garbage->status, 422);
  EXPECT_TRUE(contains(garbage->body, "not an episode file"));
}

TEST_F(ServerTest, MissingPathsAreNotFound) {
  for (const std::string target :
       {"/api/run?path=runs/none", "/api/csv?path=runs/ppo_seed0/none.csv",
        "/api/episode?path=none.tep", "/files/runs/ppo_seed0/none.txt", "/files/runs",
        "/assets/none.js", "/nothing/here"}) {
    auto answer = get(target);
    ASSERT_TRUE(answer) << target;
    EXPECT_EQ(answer->status, 404) << target;
    EXPECT_TRUE(contains(answer->body, R"({"error":)")) << target << ": " << answer->body;
  }
  auto no_path = get("/api/csv");
  ASSERT_TRUE(no_path);
  EXPECT_EQ(no_path->status, 400);
}

TEST_F(ServerTest, PathsLeadingOutsideAreRefused) {
  for (const std::string target :
       {"/files/../secret.txt", "/files/%2e%2e/secret.txt",
        "/files/runs/%2E%2E/%2e%2e/../secret.txt", "/files//etc/passwd", "/files/%2fetc%2fpasswd",
        "/api/csv?path=../secret.txt", "/api/csv?path=%2e%2e%2fsecret.txt",
        "/api/csv?path=/etc/passwd", "/api/csv?path=runs/ppo_seed0/leak.csv",
        "/files/up/secret.txt", "/api/run?path=up", "/api/episode?path=..%2Fsecret.txt",
        "/assets/../secret.txt", "/assets/%2e%2e/secret.txt"}) {
    auto answer = get(target);
    ASSERT_TRUE(answer) << target;
    EXPECT_EQ(answer->status, 403) << target << ": " << answer->body;
    EXPECT_FALSE(contains(answer->body, "outside\"")) << target;
    EXPECT_NE(answer->body, "outside") << target;
  }
}

TEST_F(ServerTest, IsReadOnly) {
  for (const char* method : {"POST", "PUT", "DELETE", "PATCH"}) {
    httplib::Request request;
    request.method = method;
    request.path = "/files/runs/ppo_seed0/config.yaml";
    request.body = "algorithm: sac\n";
    auto answer = client_->send(request);
    ASSERT_TRUE(answer) << method;
    EXPECT_EQ(answer->status, 405) << method;
  }
  std::ifstream config(directory_ / "root" / "runs" / "ppo_seed0" / "config.yaml");
  std::string first;
  std::getline(config, first);
  EXPECT_EQ(first, "algorithm: ppo");
}

TEST_F(ServerTest, FilesChangingWhileServedNeverStopTheServer) {
  const fs::path run = directory_ / "root" / "runs" / "ppo_seed0";
  // Cut the finished episode mid-record and the progress file mid-line, and flip a byte.
  std::string bytes;
  {
    std::ifstream in(run / "episodes" / "episode_0000.tep", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  for (std::size_t size : {std::size_t{0}, std::size_t{10}, std::size_t{30}, bytes.size() / 2}) {
    std::ofstream(run / "cut.tep", std::ios::binary | std::ios::trunc) << bytes.substr(0, size);
    auto answer = get("/api/episode?path=runs/ppo_seed0/cut.tep");
    ASSERT_TRUE(answer) << size;
    EXPECT_TRUE(answer->status == 200 || answer->status == 422) << size;
    EXPECT_TRUE(contains(answer->body, size < 40 ? R"({"error":)" : R"("truncated":true)"))
        << size << ": " << answer->body.substr(0, 200);
  }
  bytes[bytes.size() - 40] ^= 0x40;  // inside the last frame's payload
  std::ofstream(run / "flipped.tep", std::ios::binary) << bytes;
  auto flipped = get("/api/episode?path=runs/ppo_seed0/flipped.tep");
  ASSERT_TRUE(flipped);
  EXPECT_EQ(flipped->status, 200);
  EXPECT_TRUE(contains(flipped->body, R"("complete":false,"truncated":false,"problem":"checksum)"));
  std::ofstream(run / "progress.csv", std::ios::trunc) << "time/tot";
  auto half = get("/api/csv?path=runs/ppo_seed0/progress.csv&offset=55");
  ASSERT_TRUE(half);
  EXPECT_EQ(half->status, 200);
  EXPECT_TRUE(contains(half->body, R"("columns":[],"rows":[])")) << half->body;
  auto still = get("/api/index");
  ASSERT_TRUE(still);
  EXPECT_EQ(still->status, 200);
}

// The files a run directory names itself pass the same check as requested paths: a config.yaml
// or an episodes/ that links out of the root is neither read nor listed.
TEST_F(ServerTest, LinksNamedConfigOrEpisodesNeverLeadOutside) {
  for (const std::string target :
       {"/api/index", "/api/run?path=runs/linked_config", "/api/run?path=runs/linked_episodes",
        "/api/run?path=runs/ppo_seed0"}) {
    auto answer = get(target);
    ASSERT_TRUE(answer) << target;
    EXPECT_FALSE(contains(answer->body, "TOP-SECRET-OUTSIDE")) << target << ": " << answer->body;
    EXPECT_FALSE(contains(answer->body, "private")) << target << ": " << answer->body;
  }
  auto config = get("/api/run?path=runs/linked_config");
  ASSERT_TRUE(config);
  EXPECT_EQ(config->status, 404) << config->body;  // its only run file lies outside
  auto episodes = get("/api/run?path=runs/linked_episodes");
  ASSERT_TRUE(episodes);
  EXPECT_EQ(episodes->status, 200);
  EXPECT_TRUE(contains(episodes->body, R"("episodes":[])")) << episodes->body;
  auto run = get("/api/run?path=runs/ppo_seed0");
  ASSERT_TRUE(run);
  EXPECT_TRUE(contains(run->body, R"("name":"episode_0000.tep")"));
  EXPECT_FALSE(contains(run->body, "linked.tep")) << run->body;
  auto index = get("/api/index");
  ASSERT_TRUE(index);
  EXPECT_FALSE(contains(index->body, "runs/linked_config")) << index->body;
  EXPECT_TRUE(contains(index->body, R"("path":"runs/ppo_seed0")"));
  EXPECT_TRUE(contains(index->body, R"("episodes":3)")) << index->body;  // not linked.tep
}

// Traversal in every spelling of '..' a hostile client tries, through every endpoint, raw and
// once more percent-encoded: each is refused, missing or malformed, never an outside file.
TEST_F(ServerTest, NoSpellingOfUpLeadsOutside) {
  const std::vector<std::string> ups = {"../",
                                        "..%2f",
                                        "..%2F",
                                        "%2e%2e/",
                                        "%2e%2e%2f",
                                        "%2E%2E%2F",
                                        ".%2e/",
                                        "%2e./",
                                        "%252e%252e%252f",
                                        "..%5c",
                                        "..\\",
                                        "%c0%ae%c0%ae/",
                                        "%e0%80%ae%e0%80%ae/",
                                        "%u002e%u002e/",
                                        "....//",
                                        "..;/",
                                        "..%00/",
                                        "%2e%2e%00/",
                                        "./../",
                                        "..//",
                                        ".../",
                                        "..%252f",
                                        "%2e%2e%5c",
                                        ".%00./",
                                        "..%09/",
                                        "..%20/",
                                        "%20../"};
  std::vector<std::pair<std::string, std::string>> targets;  // (endpoint, path)
  for (const std::string& up : ups) {
    targets.emplace_back("files", up + "outside/outrun/config.yaml");
    targets.emplace_back("run", up + "outside/outrun");
    targets.emplace_back("csv", up + "outside/outrun/progress.csv");
    targets.emplace_back("episode", up + "outside/outrun/episodes/private.tep");
    targets.emplace_back("files", "runs/" + up + up + up + "outside/outrun/config.yaml");
    std::string deep;
    for (int i = 0; i < 40; ++i) deep += up;
    targets.emplace_back("files", deep + "etc/passwd");
    targets.emplace_back("assets", deep + "etc/passwd");
  }
  for (const std::string path :
       {"/etc/passwd", "%2fetc%2fpasswd", "//etc/passwd", "/./etc/passwd", "etc_link/passwd",
        "etc_link/./passwd", "link_dir/outrun/config.yaml", "link_dir/outrun/progress.csv",
        "runs/ppo_seed0/leak.csv", "runs/ppo_seed0/episodes/linked.tep", "loop/x", "loop",
        "runs/%00/../../outside/outrun/config.yaml", "file:///etc/passwd",
        "runs/ppo_seed0/config.yaml%00.csv", "~root/.bashrc", "~/.bashrc"}) {
    for (const char* endpoint : {"files", "run", "csv", "episode"}) {
      targets.emplace_back(endpoint, path);
    }
  }
  const auto encoded = [](const std::string& text) {
    std::string out;
    char hex[4];
    for (unsigned char c : text) {
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += std::isalnum(c) ? std::string(1, static_cast<char>(c)) : std::string(hex);
    }
    return out;
  };
  int requests = 0;
  for (const auto& [endpoint, path] : targets) {
    std::vector<std::string> forms{path};
    if (endpoint != "files" && endpoint != "assets") forms.push_back(encoded(path));
    for (const std::string& form : forms) {
      const std::string target = endpoint == "files"    ? "/files/" + form
                                 : endpoint == "assets" ? "/assets/" + form
                                 : endpoint == "run"    ? "/api/run?path=" + form
                                 : endpoint == "csv"    ? "/api/csv?path=" + form
                                                        : "/api/episode?path=" + form;
      const RawAnswer answer = raw_get(target);
      ++requests;
      EXPECT_TRUE(answer.status == 400 || answer.status == 403 || answer.status == 404)
          << target << " -> " << answer.status << " " << answer.body.substr(0, 200);
      for (const char* marker : {"TOP-SECRET-OUTSIDE", "MARKERCOL", "outside-episode-marker",
                                 "root:x:0:0", "outside\""}) {
        EXPECT_FALSE(contains(answer.body, marker)) << target << ": " << answer.body;
      }
    }
  }
  // '?' inside a query value is malformed for httplib, which answers 400 after its read timeout:
  // sent once.
  const RawAnswer query = raw_get("/api/csv?path=..?/outside/outrun/progress.csv");
  EXPECT_EQ(query.status, 400);
  EXPECT_FALSE(contains(query.body, "MARKERCOL"));
  EXPECT_EQ(requests, 389);
  EXPECT_EQ(raw_get("/api/csv?path=runs/ppo_seed0/eval.csv").status, 200);  // still serving
}

// One request for many byte ranges would make httplib build ranges × file size in memory.
TEST_F(ServerTest, OneByteRangePerRequest) {
  const fs::path file = directory_ / "root" / "runs" / "ppo_seed0" / "model.policy";
  const std::string content(1 << 20, 'x');
  std::ofstream(file, std::ios::binary) << content;
  std::string ranges = "Range: bytes=0-";
  for (int i = 0; i < 300; ++i) ranges += ",0-";
  const RawAnswer many =
      raw_get("/files/runs/ppo_seed0/model.policy", "Host: 127.0.0.1\r\n" + ranges + "\r\n");
  EXPECT_EQ(many.status, 416) << many.head;
  EXPECT_LT(many.body.size(), 200000u);  // not 301 copies of the file
  const RawAnswer one =
      raw_get("/files/runs/ppo_seed0/model.policy", "Host: 127.0.0.1\r\nRange: bytes=10-19\r\n");
  EXPECT_EQ(one.status, 206) << one.head;
  EXPECT_EQ(one.body, std::string(10, 'x'));
  EXPECT_EQ(raw_get("/api/index").status, 200);
}

// A second server on a port already taken fails to bind (no SO_REUSEPORT sharing the port).
TEST_F(ServerTest, ASecondServerOnTheSamePortIsRefused) {
  Server second(ServerOptions{directory_ / "root", directory_ / "page", "127.0.0.1", port_});
  EXPECT_NE(testing::error_message([&] { second.bind(); }).find("cannot listen"),
            std::string::npos);
}

// DNS rebinding: a page on another site whose name now resolves to 127.0.0.1 sends that name.
TEST_F(ServerTest, OnlyThisServersHostNamesAreAnswered) {
  const std::string port = std::to_string(port_);
  for (const std::string& host :
       std::vector<std::string>{"127.0.0.1:" + port, "localhost:" + port, "LOCALHOST", "127.0.0.1",
                                "[::1]:" + port, "dashboard.localhost:" + port}) {
    const RawAnswer answer = raw_get("/api/index", "Host: " + host + "\r\n");
    EXPECT_EQ(answer.status, 200) << host << ": " << answer.body;
  }
  for (const std::string& host :
       std::vector<std::string>{"attacker.example:" + port, "attacker.example",
                                "127.0.0.1.attacker.example", "localhost.attacker.example"}) {
    const RawAnswer answer = raw_get("/api/index", "Host: " + host + "\r\n");
    EXPECT_EQ(answer.status, 403) << host;
    EXPECT_FALSE(contains(answer.body, "ppo_seed0")) << host;
  }
  const RawAnswer twice = raw_get("/api/index", "Host: 127.0.0.1\r\nHost: attacker.example\r\n");
  EXPECT_EQ(twice.status, 403);
}

TEST_F(ServerTest, ANameTooLongToExistIsNotFound) {
  const std::string long_name(8000, 'a');
  for (const std::string& target :
       std::vector<std::string>{"/files/" + long_name, "/files/runs/" + long_name + ".csv",
                                "/api/csv?path=runs/" + std::string(300, 'b') + ".csv"}) {
    const RawAnswer answer = raw_get(target);
    EXPECT_EQ(answer.status, 404) << target.substr(0, 40) << ": " << answer.body;
  }
}

// Idle connections hold a worker each until the read timeout: a few dozen of them must not keep
// a request waiting (8 workers and a 5 s timeout kept it waiting 10 s).
TEST_F(ServerTest, IdleConnectionsDoNotHoldUpOthers) {
  std::vector<int> idle;
  for (int i = 0; i < 24; ++i) idle.push_back(connect_socket());
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto start = std::chrono::steady_clock::now();
  const RawAnswer answer = raw_get("/api/index");
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (int socket : idle) ::close(socket);
  EXPECT_EQ(answer.status, 200);
  EXPECT_LT(waited, 1.5);  // served by a free worker at once (milliseconds)
}

long peak_rss_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// A path of 100,000 points written once and then "unchanged" for 400 frames: 1.2 MB on disk,
// about 1 GB if every frame were built. Listing counts the frames without building any; the
// replay builds only as many as fit the server's episode memory.
TEST_F(ServerTest, EpisodesWhoseFramesRepeatAHugePrimitiveStaySmallInMemory) {
  const fs::path file = directory_ / "root" / "runs" / "ppo_seed0" / "episodes" / "huge.tep";
  {
    EpisodeWriter writer(file, {{"env", "Test-v0"}}, 1);
    Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Random(3, 100000);
    for (int k = 0; k <= 400; ++k) {
      EpisodeFrame frame;
      frame.step = k;
      frame.reward = k > 0 ? 1.0 : 0.0;
      frame.scene.time = 0.1 * k;
      frame.scene.paths.push_back({"path", points});
      writer.write(frame);
    }
    writer.finish();
  }
  ASSERT_LT(fs::file_size(file), 2u << 20);
  const long before = peak_rss_kb();
  auto run = get("/api/run?path=runs/ppo_seed0");
  ASSERT_TRUE(run);
  EXPECT_TRUE(contains(run->body, R"("name":"huge.tep","bytes":)")) << run->body;
  EXPECT_TRUE(contains(run->body, R"("frames":401,"complete":true,"problem":"","return":400)"))
      << run->body;
  auto replay = get("/api/episode?path=runs/ppo_seed0/episodes/huge.tep&max_frames=2000");
  ASSERT_TRUE(replay);
  EXPECT_EQ(replay->status, 200);
  EXPECT_TRUE(contains(replay->body, R"("frame_count":401,"stride":)"))
      << replay->body.substr(0, 300);
  // First and last frame always; as many as the memory allows between them.
  EXPECT_TRUE(contains(replay->body, R"({"step":0,)"));
  EXPECT_TRUE(contains(replay->body, R"({"step":400,)"));
  EXPECT_TRUE(contains(replay->body, R"("return":400,)"));
  EXPECT_LT(replay->body.size(), 4 * kEpisodeMemory);
  const long grown_mb = (peak_rss_kb() - before) / 1024;
  EXPECT_LT(grown_mb, 200) << "peak memory grew by " << grown_mb << " MB";
}

// A malformed CSV costs a bounded answer: a page of lines and the first problems with a count.
TEST_F(ServerTest, CsvAnswersComeInPagesWithTheirProblemsCounted) {
  const fs::path file = directory_ / "root" / "runs" / "ppo_seed0" / "eval.csv";
  {
    std::ofstream out(file, std::ios::trunc);
    out << "timesteps,mean_return\n";
    for (int i = 0; i < 120000; ++i) out << (i % 2 ? "1,2,3\n" : "4,5\n");
  }
  uint64_t offset = 0;
  int64_t rows = 0, problems = 0, pages = 0;
  while (true) {
    auto page = get("/api/csv?path=runs/ppo_seed0/eval.csv&offset=" + std::to_string(offset));
    ASSERT_TRUE(page);
    ASSERT_EQ(page->status, 200);
    EXPECT_LT(page->body.size(), 2000000u);
    const std::smatch found = [&] {
      std::smatch m;
      std::regex_search(page->body, m,
                        std::regex(R"re("next_offset":(\d+),.*"more":(true|false),)re"
                                   R"re("problems":\[(.*)\],"problem_count":(\d+))re"));
      return m;
    }();
    ASSERT_EQ(found.size(), 5u) << page->body.substr(page->body.size() - 300);
    offset = std::stoull(found[1]);
    problems += std::stoll(found[4]);
    const std::string listed = found[3];
    EXPECT_LE(std::count(listed.begin(), listed.end(), '"') / 2, 100);
    rows += static_cast<int64_t>(std::count(page->body.begin(), page->body.end(), '[')) - 3;
    ++pages;
    if (found[2] == "false") break;
    ASSERT_LT(pages, 10);
  }
  EXPECT_EQ(pages, 3);  // 120,000 lines, 50,000 per answer
  EXPECT_EQ(problems, 60000);
  EXPECT_EQ(rows, 60000);
}

}  // namespace
}  // namespace tendril::dashboard
