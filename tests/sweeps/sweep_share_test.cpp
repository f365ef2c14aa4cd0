#include "tendril/sweeps/sweep_share.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "support/error_message.hpp"

namespace tendril::sweeps {
namespace {

TEST(SweepShare, RanksCoverEveryRunExactlyOnce) {
  for (int ranks = 1; ranks <= 9; ++ranks) {
    for (int runs = 0; runs <= 25; ++runs) {
      std::vector<int> seen(runs, 0);
      std::size_t smallest = runs, largest = 0;
      for (int rank = 0; rank < ranks; ++rank) {
        const std::vector<int> share = SweepShare{rank, ranks, ""}.runs(runs);
        for (std::size_t k = 0; k < share.size(); ++k) {
          ASSERT_GE(share[k], 0);
          ASSERT_LT(share[k], runs);
          ++seen[share[k]];
          if (k > 0) {
            EXPECT_LT(share[k - 1], share[k]);
          }
        }
        smallest = std::min(smallest, share.size());
        largest = std::max(largest, share.size());
      }
      for (int i = 0; i < runs; ++i)
        EXPECT_EQ(seen[i], 1) << runs << " runs, " << ranks << " ranks";
      EXPECT_LE(largest - smallest, 1u);
    }
  }
  EXPECT_EQ(SweepShare({1, 3, ""}).runs(8), (std::vector<int>{1, 4, 7}));
}

TEST(SweepShare, RankOutsideTheSizeIsRefused) {
  EXPECT_NE(testing::error_message([] {
              SweepShare{3, 3, "--rank/--ranks"}.runs(5);
            }).find("--rank/--ranks"),
            std::string::npos);
}

// The launchers' variables, OpenMPI's first; each test sets only what it needs.
class LauncherEnvironment : public ::testing::Test {
 protected:
  void SetUp() override { clear(); }
  void TearDown() override { clear(); }
  static void clear() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE", "PMI_RANK", "PMI_SIZE",
                             "SLURM_PROCID", "SLURM_NTASKS"}) {
      ::unsetenv(name);
    }
  }
};

TEST_F(LauncherEnvironment, ReadsTheLaunchersRankAndSize) {
  SweepShare share = SweepShare::from_environment();
  EXPECT_EQ(share.rank, 0);
  EXPECT_EQ(share.ranks, 1);
  ::setenv("SLURM_PROCID", "2", 1);
  ::setenv("SLURM_NTASKS", "4", 1);
  share = SweepShare::from_environment();
  EXPECT_EQ(share.rank, 2);
  EXPECT_EQ(share.ranks, 4);
  ::setenv("PMI_RANK", "1", 1);
  ::setenv("PMI_SIZE", "3", 1);
  EXPECT_EQ(SweepShare::from_environment().source, "PMI_RANK/PMI_SIZE");
  ::setenv("OMPI_COMM_WORLD_RANK", "5", 1);
  ::setenv("OMPI_COMM_WORLD_SIZE", "6", 1);
  share = SweepShare::from_environment();
  EXPECT_EQ(share.rank, 5);
  EXPECT_EQ(share.ranks, 6);
  EXPECT_EQ(share.source, "OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE");
}

TEST_F(LauncherEnvironment, MalformedValuesAreErrorsNamingTheVariable) {
  ::setenv("OMPI_COMM_WORLD_RANK", "2", 1);
  ::setenv("OMPI_COMM_WORLD_SIZE", "2", 1);  // rank 2 of 2 does not exist
  EXPECT_NE(
      testing::error_message([] { SweepShare::from_environment(); }).find("OMPI_COMM_WORLD_RANK"),
      std::string::npos);
  ::setenv("OMPI_COMM_WORLD_SIZE", "4x", 1);
  EXPECT_NE(
      testing::error_message([] { SweepShare::from_environment(); }).find("OMPI_COMM_WORLD_SIZE"),
      std::string::npos);
}

}  // namespace
}  // namespace tendril::sweeps
