#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/episode_reader.hpp"
#include "tendril/core/episode_writer.hpp"

namespace tendril {
namespace {

namespace fs = std::filesystem;
using testing::error_message;

class EpisodeFileTest : public testing::ScratchDirectoryTest {
 protected:
  EpisodeFileTest() : ScratchDirectoryTest("episode_file") {}
};

// A scene with every primitive kind; the arm bends and the target moves with `k`, the rest
// stays put.
Scene scene_at(int k) {
  Scene scene;
  scene.time = 0.01 * k;
  Eigen::Matrix3Xd centreline(3, 5);
  for (int i = 0; i < 5; ++i) centreline.col(i) = Eigen::Vector3d(0.1 * k * i * i, 0.0, 0.25 * i);
  scene.rods.push_back({"arm", centreline, Eigen::VectorXd::LinSpaced(4, 0.02, 0.01)});
  scene.spheres.push_back({"target", Eigen::Vector3d(0.3, 0.1 * std::sin(k), 0.7), 0.05});
  scene.cylinders.push_back({"obstacle", {0.2, -0.5, 0.4}, {0.2, 0.5, 0.4}, 0.03, true});
  scene.boxes.push_back({"obstacle",
                         {1.0, 2.0, 3.0},
                         {0.1, 0.2, 0.3},
                         Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * k, Eigen::Vector3d::UnitZ()))});
  scene.planes.push_back({"ground", Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()});
  Eigen::Matrix3Xd nodes(3, 3);
  nodes << 0, 1, 0, 0, 0, 1, 0.01 * k, 0, 0;
  scene.lattices.push_back({"body", nodes, {{0, 1}, {1, 2}, {0, 2}}});
  Eigen::Matrix3Xd path(3, 4);
  path << 0, 1, 2, 3, 0, -1, -2, -3, 1, 1, 1, 1;
  scene.paths.push_back({"reference", path});
  scene.values.emplace_back("distance", 0.5 / (k + 1));
  return scene;
}

EpisodeFrame frame_at(int k) {
  EpisodeFrame frame;
  frame.step = k;
  frame.scene = scene_at(k);
  if (k > 0) {
    frame.reward = -0.25 * k;
    frame.action = Action(2);
    frame.action << 0.5f * static_cast<float>(k), -1.0f;
    frame.info = {{"distance", 0.5 / (k + 1)}, {"is_success", 0.0}};
  }
  return frame;
}

Eigen::MatrixXd as_float(const Eigen::MatrixXd& m) { return m.cast<float>().cast<double>(); }
double as_float(double v) { return static_cast<double>(static_cast<float>(v)); }

// What a frame reads back as: every array through float32; time and reward exact.
void expect_same_frame(const EpisodeFrame& read, const EpisodeFrame& written) {
  EXPECT_EQ(read.step, written.step);
  EXPECT_EQ(read.scene.time, written.scene.time);
  EXPECT_EQ(read.reward, written.reward);
  EXPECT_EQ(read.terminated, written.terminated);
  EXPECT_EQ(read.truncated, written.truncated);
  EXPECT_EQ(read.action, written.action);
  ASSERT_EQ(read.info.size(), written.info.size());
  for (size_t i = 0; i < read.info.size(); ++i) {
    EXPECT_EQ(read.info[i].first, written.info[i].first);
    EXPECT_EQ(read.info[i].second, as_float(written.info[i].second));
  }
  const Scene &a = read.scene, &b = written.scene;
  ASSERT_EQ(a.rods.size(), b.rods.size());
  for (size_t i = 0; i < a.rods.size(); ++i) {
    EXPECT_EQ(a.rods[i].role, b.rods[i].role);
    EXPECT_EQ(Eigen::MatrixXd(a.rods[i].centreline), as_float(b.rods[i].centreline));
    EXPECT_EQ(Eigen::MatrixXd(a.rods[i].radii), as_float(b.rods[i].radii));
  }
  ASSERT_EQ(a.spheres.size(), b.spheres.size());
  for (size_t i = 0; i < a.spheres.size(); ++i) {
    EXPECT_EQ(a.spheres[i].role, b.spheres[i].role);
    EXPECT_EQ(Eigen::MatrixXd(a.spheres[i].centre), as_float(b.spheres[i].centre));
    EXPECT_EQ(a.spheres[i].radius, as_float(b.spheres[i].radius));
  }
  ASSERT_EQ(a.cylinders.size(), b.cylinders.size());
  for (size_t i = 0; i < a.cylinders.size(); ++i) {
    EXPECT_EQ(Eigen::MatrixXd(a.cylinders[i].start), as_float(b.cylinders[i].start));
    EXPECT_EQ(Eigen::MatrixXd(a.cylinders[i].end), as_float(b.cylinders[i].end));
    EXPECT_EQ(a.cylinders[i].radius, as_float(b.cylinders[i].radius));
    EXPECT_EQ(a.cylinders[i].capped, b.cylinders[i].capped);
  }
  ASSERT_EQ(a.boxes.size(), b.boxes.size());
  for (size_t i = 0; i < a.boxes.size(); ++i) {
    EXPECT_EQ(Eigen::MatrixXd(a.boxes[i].centre), as_float(b.boxes[i].centre));
    EXPECT_EQ(Eigen::MatrixXd(a.boxes[i].half_extents), as_float(b.boxes[i].half_extents));
    EXPECT_EQ(Eigen::MatrixXd(a.boxes[i].orientation.coeffs()),
              as_float(b.boxes[i].orientation.coeffs()));
  }
  ASSERT_EQ(a.planes.size(), b.planes.size());
  for (size_t i = 0; i < a.planes.size(); ++i) {
    EXPECT_EQ(a.planes[i].role, b.planes[i].role);
    EXPECT_EQ(Eigen::MatrixXd(a.planes[i].normal), as_float(b.planes[i].normal));
  }
  ASSERT_EQ(a.lattices.size(), b.lattices.size());
  for (size_t i = 0; i < a.lattices.size(); ++i) {
    EXPECT_EQ(Eigen::MatrixXd(a.lattices[i].nodes), as_float(b.lattices[i].nodes));
    EXPECT_EQ(a.lattices[i].springs, b.lattices[i].springs);
  }
  ASSERT_EQ(a.paths.size(), b.paths.size());
  for (size_t i = 0; i < a.paths.size(); ++i) {
    EXPECT_EQ(Eigen::MatrixXd(a.paths[i].points), as_float(b.paths[i].points));
  }
  ASSERT_EQ(a.values.size(), b.values.size());
  for (size_t i = 0; i < a.values.size(); ++i) {
    EXPECT_EQ(a.values[i].first, b.values[i].first);
    EXPECT_EQ(a.values[i].second, as_float(b.values[i].second));
  }
}

fs::path write_episode(const fs::path& file, int frames, bool finish = true) {
  EpisodeWriter writer(file, {{"env", "Test/Scene-v0"}, {"policy", "none"}}, 2);
  for (int k = 0; k < frames; ++k) writer.write(frame_at(k));
  if (finish) writer.finish();
  return file;
}

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_raw(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(Crc32, KnownCheckValue) {
  // The CRC-32 check value of the ASCII digits "123456789" (zlib, PNG).
  EXPECT_EQ(crc32("123456789", 9), 0xCBF43926u);
  EXPECT_EQ(crc32("", 0), 0u);
}

TEST_F(EpisodeFileTest, RoundTripGivesTheSameFramesThroughFloat32) {
  const fs::path file = write_episode(directory_ / "a.tep", 6);
  const Episode episode = read_episode(file);
  EXPECT_EQ(episode.meta("env"), "Test/Scene-v0");
  EXPECT_EQ(episode.meta("policy"), "none");
  EXPECT_EQ(episode.meta("missing", "fallback"), "fallback");
  EXPECT_EQ(episode.action_size, 2);
  ASSERT_EQ(episode.frames.size(), 6u);
  for (int k = 0; k < 6; ++k) expect_same_frame(episode.frames[k], frame_at(k));
  ASSERT_TRUE(episode.summary.has_value());
  EXPECT_EQ(episode.summary->steps, 5);
  EXPECT_EQ(episode.summary->episode_return, -0.25 * (1 + 2 + 3 + 4 + 5));
  EXPECT_FALSE(episode.summary->terminated);
}

TEST_F(EpisodeFileTest, PrimitivesThatDoNotChangeAreStoredOnce) {
  auto file_size = [&](int frames, bool moving) {
    const fs::path file =
        directory_ / ((moving ? "moving_" : "still_") + std::to_string(frames) + ".tep");
    EpisodeWriter writer(file, {}, 2);
    for (int k = 1; k <= frames; ++k) writer.write(frame_at(moving ? k : 1));
    writer.finish();
    return fs::file_size(file);
  };
  // A frame's fixed part: step, time, reward, flags, 2 action values, 2 info values, 1 scene
  // value, the change mask (7 primitives: 1 byte) and the record's framing.
  const std::size_t fixed = 4 + 8 + 8 + 1 + 2 * 4 + 2 * 4 + 4 + 1 + 9;
  EXPECT_EQ(file_size(11, false) - file_size(1, false), 10 * fixed);
  // Moving frames rewrite the arm (15 + 4 floats), target (4), box (10) and lattice (9); the
  // cylinder, plane and path are stored once.
  EXPECT_EQ(file_size(11, true) - file_size(1, true), 10 * (fixed + 4 * (19 + 4 + 10 + 9)));
  const Episode episode = read_episode(directory_ / "still_11.tep");
  ASSERT_EQ(episode.frames.size(), 11u);
  for (const EpisodeFrame& frame : episode.frames) expect_same_frame(frame, frame_at(1));
}

// Reading some frames gives exactly those frames of the whole reading, even when the ones
// before them changed primitives that the chosen ones leave unchanged; the outline counts every
// frame and its reward without building any.
TEST_F(EpisodeFileTest, ChosenFramesAndTheOutlineAgreeWithTheWholeReading) {
  const fs::path file = directory_ / "mixed.tep";
  {
    EpisodeWriter writer(file, {{"env", "Test/Scene-v0"}}, 2);
    for (int k = 0; k < 12; ++k) writer.write(frame_at(k % 3 == 2 ? k - 1 : k));  // repeats
    writer.finish();
  }
  const Episode whole = read_episode(file);
  const std::vector<int64_t> chosen = {0, 2, 3, 8, 11};
  const PartialEpisode some = read_partial_episode(file, chosen);
  EXPECT_TRUE(some.problem.empty());
  ASSERT_EQ(some.episode.frames.size(), chosen.size());
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    expect_same_frame(some.episode.frames[i], whole.frames[static_cast<std::size_t>(chosen[i])]);
  }
  EXPECT_TRUE(read_partial_episode(file, {}).episode.frames.empty());

  const EpisodeOutline outline = outline_episode(file);
  EXPECT_EQ(outline.metadata, whole.metadata);
  EXPECT_EQ(outline.action_size, 2);
  ASSERT_EQ(outline.frames(), 12);
  for (std::size_t k = 0; k < 12; ++k) EXPECT_EQ(outline.rewards[k], whole.frames[k].reward);
  ASSERT_TRUE(outline.summary.has_value());
  EXPECT_EQ(outline.summary->episode_return, whole.summary->episode_return);
  EXPECT_TRUE(outline.problem.empty());
  // The frame estimate covers what a frame holds: 7 primitives' doubles and more.
  EXPECT_GT(outline.frame_bytes, sizeof(double) * (19 + 4 + 7 + 10 + 6 + 9 + 12));
  EXPECT_LT(outline.frame_bytes, 8192u);

  // A cut file: the outline says what read_partial_episode says.
  const std::string bytes = read_file(file);
  write_raw(directory_ / "cut.tep", bytes.substr(0, bytes.size() * 2 / 3));
  const PartialEpisode cut = read_partial_episode(directory_ / "cut.tep");
  const EpisodeOutline cut_outline = outline_episode(directory_ / "cut.tep");
  EXPECT_EQ(cut_outline.frames(), static_cast<int64_t>(cut.episode.frames.size()));
  EXPECT_EQ(cut_outline.problem, cut.problem);
  EXPECT_EQ(cut_outline.truncated, cut.truncated);
  EXPECT_FALSE(cut_outline.summary.has_value());
}

TEST_F(EpisodeFileTest, ASceneThatChangesItsStructureStartsANewLayout) {
  const fs::path file = directory_ / "layouts.tep";
  std::vector<EpisodeFrame> frames = {frame_at(0), frame_at(1), frame_at(2), frame_at(3)};
  frames[2].scene.spheres.push_back({"goal", {1, 1, 1}, 0.1});
  frames[2].info.emplace_back("collision", 1.0);
  frames[3].scene.rods.clear();
  {
    EpisodeWriter writer(file, {}, 2);
    for (const EpisodeFrame& frame : frames) writer.write(frame);
    writer.finish();
  }
  const Episode episode = read_episode(file);
  ASSERT_EQ(episode.frames.size(), 4u);
  for (int k = 0; k < 4; ++k) expect_same_frame(episode.frames[k], frames[k]);
}

TEST_F(EpisodeFileTest, NothingIsOverwritten) {
  const fs::path file = write_episode(directory_ / "kept.tep", 2);
  const std::string before = read_file(file);
  EXPECT_NE(error_message([&] { EpisodeWriter(file, {}, 2); }).find("exists already"),
            std::string::npos);
  EXPECT_EQ(read_file(file), before);
}

TEST_F(EpisodeFileTest, AWrongActionSizeIsRefused) {
  EpisodeWriter writer(directory_ / "action.tep", {}, 3);
  EpisodeFrame frame = frame_at(1);  // two action values
  EXPECT_NE(error_message([&] { writer.write(frame); }).find("expected 3"), std::string::npos);
}

TEST_F(EpisodeFileTest, AnUnfinishedRecordingReadsAsIncompleteWithItsFrames) {
  const fs::path file = write_episode(directory_ / "open.tep", 4, /*finish=*/false);
  EXPECT_NE(error_message([&] { read_episode(file); }).find("no end record"), std::string::npos);
  const PartialEpisode partial = read_partial_episode(file);
  EXPECT_TRUE(partial.truncated);
  EXPECT_FALSE(partial.episode.summary.has_value());
  ASSERT_EQ(partial.episode.frames.size(), 4u);
  expect_same_frame(partial.episode.frames[3], frame_at(3));
}

TEST_F(EpisodeFileTest, EveryCutOfTheFileKeepsTheWholeFramesBeforeIt) {
  const fs::path file = write_episode(directory_ / "whole.tep", 5);
  const std::string bytes = read_file(file);
  std::size_t previous_frames = 0;
  for (std::size_t size = 200; size < bytes.size(); size += 7) {
    write_raw(directory_ / "cut.tep", bytes.substr(0, size));
    const PartialEpisode partial = read_partial_episode(directory_ / "cut.tep");
    EXPECT_TRUE(partial.truncated) << size;
    EXPECT_FALSE(partial.problem.empty());
    EXPECT_GE(partial.episode.frames.size(), previous_frames);
    previous_frames = partial.episode.frames.size();
  }
  EXPECT_EQ(previous_frames, 5u);
}

TEST_F(EpisodeFileTest, AFlippedByteIsACorruptRecordNamedByItsOffset) {
  const fs::path file = write_episode(directory_ / "flip.tep", 5);
  std::string bytes = read_file(file);
  const std::size_t at = bytes.size() - 60;  // inside the last frame
  bytes[at] = static_cast<char>(bytes[at] ^ 0x10);
  write_raw(file, bytes);
  const std::string message = error_message([&] { read_episode(file); });
  EXPECT_NE(message.find("checksum mismatch"), std::string::npos) << message;
  EXPECT_NE(message.find(file.string()), std::string::npos);
  const PartialEpisode partial = read_partial_episode(file);
  EXPECT_FALSE(partial.truncated);
  EXPECT_EQ(partial.episode.frames.size(), 4u);
}

// Found by tests/fuzz/episode_fuzz: a layout record (with right checksums) claiming an action of
// 4294967217 floats made the frame reader allocate 16 GiB before noticing that its record holds
// 29 bytes. The header, that layout and one frame record, as the fuzzer wrote them; then the same
// with an action of 2^30 floats, which only the frame's size check refuses.
TEST_F(EpisodeFileTest, SizesBeyondTheRecordAreRefusedBeforeAllocating) {
  const std::string hex =
      "74656e6472696c2d657069736f64650a4817000000010000000100000003000000656e7604000000"
      "7365656461b370bd4c1c000000b1ffffff00000000010000000800000064697374616e6365000000"
      "0060764b37461d00000074656e6472696c2d65736f647065690a4817000000010000000100000086"
      "4afc2d";
  std::string bytes;
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    bytes.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  }
  const fs::path file = directory_ / "huge_action.tep";
  write_raw(file, bytes);
  std::string message = error_message([&] { read_episode(file); });
  EXPECT_NE(message.find("an action of 4294967217 numbers"), std::string::npos) << message;

  // The layout record: tag at byte 48, u32 length 28, payload from byte 53 (the action size
  // first), its CRC-32 at byte 81.
  const uint32_t action_size = 1u << 30;
  std::memcpy(bytes.data() + 53, &action_size, sizeof action_size);
  const uint32_t crc = crc32(bytes.data() + 48, 5 + 28);
  std::memcpy(bytes.data() + 81, &crc, sizeof crc);
  write_raw(file, bytes);
  message = error_message([&] { read_episode(file); });
  EXPECT_NE(message.find("record ends inside a field"), std::string::npos) << message;
  const PartialEpisode partial = read_partial_episode(file);
  EXPECT_EQ(partial.episode.action_size, 1 << 30);
  EXPECT_TRUE(partial.episode.frames.empty());
  EXPECT_NE(partial.problem.find("at byte 85"), std::string::npos) << partial.problem;
}

TEST_F(EpisodeFileTest, OtherFilesAreNotEpisodes) {
  write_raw(directory_ / "text.tep", "timesteps,mean\n1,2\n");
  EXPECT_NE(error_message([&] {
              read_partial_episode(directory_ / "text.tep");
            }).find("not an episode file"),
            std::string::npos);
  EXPECT_NE(error_message([&] { read_episode(directory_ / "missing.tep"); }).find("cannot open"),
            std::string::npos);
  const std::string bytes = read_file(write_episode(directory_ / "b.tep", 1));
  write_raw(directory_ / "header_only.tep", bytes.substr(0, 20));
  EXPECT_NE(error_message([&] {
              read_partial_episode(directory_ / "header_only.tep");
            }).find("unreadable header"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril
