// Core pieces of fault-tolerant runs: the run-directory lock, the interrupt flag, checked
// appends on a full disk or under a file-size limit, scalar logs that drop what was logged
// after a checkpoint, bounded config input.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/atomic_file.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/interrupt.hpp"
#include "tendril/core/run_lock.hpp"
#include "tendril/core/scalar_log.hpp"

namespace tendril {
namespace {

namespace fs = std::filesystem;
using testing::error_message;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class RunFaults : public testing::ScratchDirectoryTest {
 protected:
  RunFaults() : ScratchDirectoryTest("core_faults") {}
};

TEST_F(RunFaults, SecondLockIsRefusedNamingTheHolder) {
  std::optional<RunLock> first(std::in_place, directory_);
  EXPECT_EQ(read_text(directory_ / "run.lock"), std::to_string(::getpid()) + "\n");
  const std::string message = error_message([&] { RunLock second(directory_); });
  EXPECT_NE(message.find("in use by process " + std::to_string(::getpid())), std::string::npos)
      << message;
  first.reset();
  EXPECT_EQ(read_text(directory_ / "run.lock"), "");  // released: no stale PID left
  EXPECT_NO_THROW(RunLock again(directory_));
}

// try_take passes over a held lock without waiting or raising, and takes a free or stale one.
TEST_F(RunFaults, TryTakeGivesNothingWhileAnotherHolds) {
  std::optional<RunLock> first = RunLock::try_take(directory_);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(read_text(directory_ / "run.lock"), std::to_string(::getpid()) + "\n");
  EXPECT_FALSE(RunLock::try_take(directory_).has_value());
  EXPECT_EQ(read_text(directory_ / "run.lock"), std::to_string(::getpid()) + "\n");
  first.reset();
  { std::ofstream(directory_ / "run.lock") << "999999\n"; }  // left by a killed process
  EXPECT_TRUE(RunLock::try_take(directory_).has_value());
  EXPECT_EQ(read_text(directory_ / "run.lock"), "");
}

// The lock of a process killed with SIGKILL goes with it; its PID file stays and is taken over.
TEST_F(RunFaults, LockOfAKilledProcessIsStale) {
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    RunLock held(directory_);
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(2);
    ::pause();
    ::_exit(0);
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  const std::string message = error_message([&] { RunLock second(directory_); });
  EXPECT_NE(message.find("in use by process " + std::to_string(child)), std::string::npos)
      << message;
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  EXPECT_EQ(read_text(directory_ / "run.lock"), std::to_string(child) + "\n");
  const RunLock taken(directory_);
  EXPECT_EQ(read_text(directory_ / "run.lock"), std::to_string(::getpid()) + "\n");
  ::close(ready[0]);
  ::close(ready[1]);
}

TEST(Interrupt, FirstSignalIsRecordedSecondTakesTheDefaultAction) {
  clear_interrupt();
  catch_interrupts();
  std::raise(SIGTERM);
  EXPECT_EQ(interrupt_signal(), SIGTERM);
  clear_interrupt();
  EXPECT_EQ(interrupt_signal(), 0);
  // The handler was reset: a second SIGTERM ends a process (checked in a child).
  const pid_t child = ::fork();
  if (child == 0) {
    std::raise(SIGTERM);
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  std::signal(SIGINT, SIG_DFL);
}

TEST_F(RunFaults, AppendsToAFullDiskRaiseErrorNamingTheFile) {
  const std::string message =
      error_message([] { append_to_file("/dev/full", "row\n", "eval.csv"); });
  EXPECT_NE(message.find("/dev/full"), std::string::npos) << message;
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
}

// A file-size limit (RLIMIT_FSIZE) fails writes as a full disk does, for this process only.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    std::signal(SIGXFSZ, SIG_IGN);
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() { ::setrlimit(RLIMIT_FSIZE, &saved_); }

 private:
  rlimit saved_{};
};

TEST_F(RunFaults, ScalarLogOnAFullDiskRaisesErrorNamingTheFile) {
  ScalarLog log(directory_);
  log.record("time/total_timesteps", 1.0);
  log.dump(1);
  std::string message;
  {
    const FileSizeLimit limit(200);
    message = error_message([&] {
      for (int step = 2; step < 100; ++step) {
        log.record("time/total_timesteps", step);
        log.dump(step);
      }
    });
  }
  EXPECT_NE(message.find(directory_.string()), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  // Every event record written is whole: the file reads back.
  EXPECT_NO_THROW(read_event_scalars(log.event_path()));
}

TEST_F(RunFaults, ResumedScalarLogDropsWhatWasLoggedAfterTheCheckpoint) {
  fs::path first_events;
  {
    ScalarLog log(directory_);
    for (int step = 100; step <= 500; step += 100) {
      log.record("time/total_timesteps", step);
      log.record("rollout/ep_rew_mean", -step);
      log.dump(step);
    }
    first_events = log.event_path();
  }
  std::ofstream(first_events, std::ios::app | std::ios::binary) << "torn";
  {
    ScalarLog resumed(directory_, /*resume=*/true, /*resume_step=*/300);
    resumed.record("time/total_timesteps", 400);
    resumed.record("rollout/ep_rew_mean", -400);
    resumed.dump(400);
  }
  EXPECT_EQ(read_text(directory_ / "progress.csv"),
            "rollout/ep_rew_mean,time/total_timesteps\n-100,100\n-200,200\n-300,300\n-400,400\n");
  const auto earlier = read_event_scalars(first_events);
  ASSERT_EQ(earlier.size(), 6u);  // two tags at 100, 200, 300
  EXPECT_EQ(earlier.back().step, 300);
  EXPECT_EQ(truncate_event_file(first_events, 300), 0);  // already one timeline
  EXPECT_EQ(truncate_event_file(first_events, 200), 1);
  EXPECT_EQ(read_event_scalars(first_events).size(), 4u);
}

TEST_F(RunFaults, ConfigInputIsBounded) {
  EXPECT_NE(error_message([] { Config::load_file("/dev/zero"); }).find("not a regular file"),
            std::string::npos);
  EXPECT_NE(error_message([&] { Config::load_file(directory_); }).find("is a directory"),
            std::string::npos);
  const fs::path big = directory_ / "big.yaml";
  std::ofstream(big) << "# " << std::string(Config::kMaxFileBytes, 'x') << "\nseed: 1\n";
  const std::string too_big = error_message([&] { Config::load_file(big); });
  EXPECT_NE(too_big.find("larger than 1 MiB"), std::string::npos) << too_big;
  std::ofstream(big, std::ios::trunc)
      << "# " << std::string(Config::kMaxFileBytes - 20, 'x') << "\nseed: 1\n";
  EXPECT_EQ(Config::load_file(big).get<int>("seed"), 1);

  Config config = Config::parse("seed: 1\n");
  const std::string long_value(Config::kMaxValueBytes + 1, '7');
  EXPECT_NE(error_message([&] { config.set("seed", long_value); }).find("at most 65536"),
            std::string::npos);
  // A long value is quoted cut short in messages.
  config.set("seed", std::string(1000, 'z'));
  const std::string message = error_message([&] { config.get<int>("seed"); });
  EXPECT_LT(message.size(), 200u) << message;
  EXPECT_NE(message.find("(1000 bytes)"), std::string::npos) << message;
}

TEST(AtomicFile, LeftoversAreRecognisedByName) {
  EXPECT_TRUE(is_atomic_write_leftover("step_4096.ckpt.tmp.1234"));
  EXPECT_TRUE(is_atomic_write_leftover("eval.csv.tmp.7"));
  EXPECT_FALSE(is_atomic_write_leftover("eval.csv.tmp."));
  EXPECT_FALSE(is_atomic_write_leftover("notes.tmp.txt"));
  EXPECT_FALSE(is_atomic_write_leftover(".tmp.12"));
  EXPECT_FALSE(is_atomic_write_leftover("step_4096.ckpt"));
}

}  // namespace
}  // namespace tendril
