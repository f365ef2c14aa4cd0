#include "tendril/dashboard/served_root.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

namespace tendril::dashboard {
namespace {

namespace fs = std::filesystem;

class ServedRootTest : public testing::ScratchDirectoryTest {
 protected:
  ServedRootTest() : ScratchDirectoryTest("served_root") {}
  void SetUp() override {
    ScratchDirectoryTest::SetUp();
    fs::create_directories(directory_ / "root" / "run" / "episodes");
    std::ofstream(directory_ / "root" / "run" / "progress.csv") << "a\n1\n";
    std::ofstream(directory_ / "secret.txt") << "outside";
    fs::create_directories(directory_ / "root_sibling");
  }
};

TEST_F(ServedRootTest, ResolvesPathsInsideTheRoot) {
  const ServedRoot root(directory_ / "root");
  const fs::path canonical = fs::canonical(directory_ / "root");
  EXPECT_EQ(root.resolve(""), canonical);
  EXPECT_EQ(root.resolve("."), canonical);
  EXPECT_EQ(root.resolve("run/progress.csv"), canonical / "run" / "progress.csv");
  EXPECT_EQ(root.resolve("run//./progress.csv"), canonical / "run" / "progress.csv");
  EXPECT_EQ(root.resolve("run/not-yet-written.csv"), canonical / "run" / "not-yet-written.csv");
  EXPECT_EQ(root.relative(canonical / "run" / "progress.csv"), "run/progress.csv");
  EXPECT_EQ(root.relative(canonical), "");
}

TEST_F(ServedRootTest, RefusesEveryWayOut) {
  const ServedRoot root(directory_ / "root");
  for (const std::string& path : std::vector<std::string>{
           "..", "../secret.txt", "run/../../secret.txt", "run/..", "/etc/passwd",
           (directory_ / "secret.txt").string(), "../root_sibling", std::string("run\0x", 5)}) {
    EXPECT_FALSE(root.resolve(path).has_value()) << path;
  }
  // A symbolic link inside the root that points outside it, to a file or a directory.
  fs::create_symlink(directory_ / "secret.txt", directory_ / "root" / "run" / "leak.txt");
  fs::create_directory_symlink(directory_, directory_ / "root" / "up");
  EXPECT_FALSE(root.resolve("run/leak.txt").has_value());
  EXPECT_FALSE(root.resolve("up/secret.txt").has_value());
  EXPECT_FALSE(root.resolve("up").has_value());
  // A link that stays inside is followed.
  fs::create_directory_symlink(directory_ / "root" / "run", directory_ / "root" / "latest");
  EXPECT_EQ(root.resolve("latest/progress.csv"),
            fs::canonical(directory_ / "root" / "run" / "progress.csv"));
}

// Paths the server derives itself (a run's config.yaml, episodes/) pass the same check.
TEST_F(ServedRootTest, DerivedPathsAreContainedLikeRequestedOnes) {
  const ServedRoot root(directory_ / "root");
  const fs::path run = fs::canonical(directory_ / "root" / "run");
  EXPECT_EQ(root.served_file(run / "progress.csv"), run / "progress.csv");
  EXPECT_FALSE(root.served_file(run / "episodes").has_value());  // a directory
  EXPECT_FALSE(root.served_file(run / "missing.yaml").has_value());
  EXPECT_EQ(root.contain(run / "episodes"), run / "episodes");
  fs::create_symlink(directory_ / "secret.txt", run / "config.yaml");
  fs::create_directory_symlink(directory_ / "root_sibling", run / "linked");
  fs::create_symlink(run / "progress.csv", run / "inside.csv");
  EXPECT_FALSE(root.served_file(run / "config.yaml").has_value());
  EXPECT_FALSE(root.contain(run / "linked").has_value());
  EXPECT_FALSE(root.contain(run / "linked" / "x.tep").has_value());
  EXPECT_EQ(root.served_file(run / "inside.csv"), run / "progress.csv");
  EXPECT_FALSE(root.contain(directory_ / "secret.txt").has_value());
}

TEST_F(ServedRootTest, NamesTooLongForTheFileSystemCannotExist) {
  EXPECT_TRUE(ServedRoot::nameable("run/progress.csv"));
  EXPECT_TRUE(ServedRoot::nameable(std::string(255, 'a') + "/b"));
  EXPECT_FALSE(ServedRoot::nameable(std::string(256, 'a')));
  EXPECT_FALSE(ServedRoot::nameable("run/" + std::string(8000, 'a')));
  std::string deep;
  for (int i = 0; i < 1000; ++i) deep += "abcd/";
  EXPECT_FALSE(ServedRoot::nameable(deep));  // 5,000 characters: longer than any path
}

TEST_F(ServedRootTest, TheRootMustBeADirectory) {
  EXPECT_NE(
      testing::error_message([&] { ServedRoot(directory_ / "missing"); }).find("not a directory"),
      std::string::npos);
  EXPECT_NE(testing::error_message([&] {
              ServedRoot(directory_ / "secret.txt");
            }).find("not a directory"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::dashboard
