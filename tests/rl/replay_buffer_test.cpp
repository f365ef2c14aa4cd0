#include "tendril/rl/replay_buffer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/error_message.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

// Transition i: observation (i, −i), action i/10, reward i, next observation (i+1, −i−1),
// terminated on multiples of 3.
void add_transitions(ReplayBuffer& buffer, int first, int count) {
  for (int i = first; i < first + count; ++i) {
    const auto value = static_cast<float>(i);
    buffer.add(Eigen::Vector2f(value, -value), Eigen::VectorXf::Constant(1, value / 10.0f), value,
               Eigen::Vector2f(value + 1.0f, -value - 1.0f), i % 3 == 0);
  }
}

fs::path temporary_file(const std::string& name) {
  return fs::temp_directory_path() / ("tendril_replay_" + name + "_" + std::to_string(::getpid()));
}

TEST(ReplayBuffer, KeepsTheNewestTransitionsInARing) {
  ReplayBuffer buffer(4, 2, 1);
  add_transitions(buffer, 0, 3);
  EXPECT_EQ(buffer.size(), 3);
  add_transitions(buffer, 3, 3);  // 4 and 5 overwrite slots 0 and 1
  EXPECT_EQ(buffer.size(), 4);
  EXPECT_EQ(buffer.reward(0), 4.0f);
  EXPECT_EQ(buffer.reward(1), 5.0f);
  EXPECT_EQ(buffer.reward(2), 2.0f);
  EXPECT_TRUE(buffer.terminated(3));
  EXPECT_EQ(buffer.next_observation(1), Eigen::Vector2f(6.0f, -6.0f));
}

TEST(ReplayBuffer, SamplesConsistentTransitionsReproducibly) {
  ReplayBuffer buffer(100, 2, 1);
  add_transitions(buffer, 0, 50);
  ReplayBuffer::Batch a, b;
  Rng rng_a(5), rng_b(5);
  buffer.sample(64, rng_a, a);
  buffer.sample(64, rng_b, b);
  EXPECT_EQ(a.observations, b.observations);
  EXPECT_EQ(a.observations.cols(), 64);
  for (int i = 0; i < 64; ++i) {
    const float index = a.rewards[i];
    EXPECT_GE(index, 0.0f);
    EXPECT_LT(index, 50.0f);  // only filled slots
    EXPECT_EQ(a.observations(0, i), index);
    EXPECT_EQ(a.actions(0, i), index / 10.0f);
    EXPECT_EQ(a.next_observations(1, i), -index - 1.0f);
    EXPECT_EQ(a.terminated[i], static_cast<int>(index) % 3 == 0 ? 1.0f : 0.0f);
  }
}

TEST(ReplayBuffer, SamplingIsUniform) {
  ReplayBuffer buffer(10, 2, 1);
  add_transitions(buffer, 0, 10);
  ReplayBuffer::Batch batch;
  Rng rng(1);
  std::vector<int> counts(10, 0);
  for (int round = 0; round < 1000; ++round) {
    buffer.sample(100, rng, batch);
    for (int i = 0; i < 100; ++i) ++counts[static_cast<int>(batch.rewards[i])];
  }
  for (int count : counts) EXPECT_NEAR(count, 10000, 400);  // ±4σ of Binomial(1e5, 0.1)
}

TEST(ReplayBuffer, SaveLoadRoundTripsExactly) {
  ReplayBuffer buffer(8, 2, 1);
  add_transitions(buffer, 0, 11);  // wrapped
  const fs::path file = temporary_file("roundtrip");
  buffer.save(file);
  ReplayBuffer restored(8, 2, 1);
  restored.load(file);
  EXPECT_EQ(restored.size(), 8);
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(restored.observation(i), buffer.observation(i));
    EXPECT_EQ(restored.action(i), buffer.action(i));
    EXPECT_EQ(restored.reward(i), buffer.reward(i));
    EXPECT_EQ(restored.next_observation(i), buffer.next_observation(i));
    EXPECT_EQ(restored.terminated(i), buffer.terminated(i));
  }
  // The ring position survives: the next transition overwrites the same slot in both.
  add_transitions(buffer, 100, 1);
  add_transitions(restored, 100, 1);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(restored.reward(i), buffer.reward(i));
  fs::remove(file);
}

TEST(ReplayBuffer, CorruptTruncatedOrMismatchingFilesAreRefusedAndChangeNothing) {
  ReplayBuffer buffer(8, 2, 1);
  add_transitions(buffer, 0, 5);
  const fs::path file = temporary_file("corrupt");
  buffer.save(file);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ReplayBuffer target(8, 2, 1);
  add_transitions(target, 50, 2);

  std::string flipped = bytes;
  flipped[100] = static_cast<char>(flipped[100] ^ 0x10);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << flipped;
  EXPECT_NE(testing::error_message([&] { target.load(file); }).find("checksum"), std::string::npos);

  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 7);
  EXPECT_NE(testing::error_message([&] { target.load(file); }).find("truncated"),
            std::string::npos);

  std::ofstream(file, std::ios::binary | std::ios::trunc) << "not a buffer";
  EXPECT_NE(testing::error_message([&] { target.load(file); }).find("not a replay buffer"),
            std::string::npos);

  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  ReplayBuffer other_shape(8, 3, 1);
  EXPECT_NE(testing::error_message([&] { other_shape.load(file); }).find("does not fit"),
            std::string::npos);
  EXPECT_NE(
      testing::error_message([&] { target.load(file.string() + ".missing"); }).find("cannot open"),
      std::string::npos);

  // Nothing of the failed loads reached the buffer.
  EXPECT_EQ(target.size(), 2);
  EXPECT_EQ(target.reward(0), 50.0f);
  EXPECT_EQ(target.reward(1), 51.0f);
  fs::remove(file);
}

TEST(ReplayBuffer, RejectsBadShapesAndEmptySampling) {
  EXPECT_NE(testing::error_message([] { ReplayBuffer(0, 2, 1); }).find("capacity"),
            std::string::npos);
  ReplayBuffer buffer(4, 2, 1);
  ReplayBuffer::Batch batch;
  Rng rng(0);
  EXPECT_NE(testing::error_message([&] { buffer.sample(2, rng, batch); }).find("empty"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::rl
