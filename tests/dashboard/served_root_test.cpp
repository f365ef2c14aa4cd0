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
