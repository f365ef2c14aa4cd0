#include "tendril/dashboard/server.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

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

    server_ = std::make_unique<Server>(
        ServerOptions{directory_ / "root", directory_ / "page", "127.0.0.1", 0});
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

  static void write_episode(const fs::path& file, int frames, bool finish) {
    EpisodeWriter writer(file, {{"env", "Test-v0"}}, 1);
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

}  // namespace
}  // namespace tendril::dashboard
