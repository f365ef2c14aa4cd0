#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tendril/core/episode.hpp"

namespace tendril {

// Reads an episode file (docs/episode_format.md), verifying every record's CRC-32. Raises Error
// naming the file and the byte offset when it is not an episode file, is damaged, or lacks its
// end record.
Episode read_episode(const std::filesystem::path& file);

// What can be read of an episode file that is still being written, was cut short or is damaged
// past some point: the frames before the first problem, and the problem. Raises Error only when
// the file cannot be read or is not an episode file at all (wrong magic or header).
struct PartialEpisode {
  Episode episode;
  std::string problem;     // empty when the file is complete and intact
  bool truncated = false;  // it ends inside a record or before its end record
};
PartialEpisode read_partial_episode(const std::filesystem::path& file);

// As read_partial_episode, keeping only the frames whose indices (0-based, ascending) `frames`
// lists: the others are read and checked but never built, so memory grows with the frames kept,
// not with the file (a frame that leaves its primitives unchanged costs a bit in the file and a
// whole scene in memory).
PartialEpisode read_partial_episode(const std::filesystem::path& file,
                                    const std::vector<int64_t>& frames);

// What a listing shows of an episode file and what a reader of some of its frames must know
// first, read as read_partial_episode reads (every record checked) without building any frame:
// memory grows with the number of frames only.
struct EpisodeOutline {
  EpisodeMetadata metadata;
  int action_size = 0;
  std::vector<double> rewards;  // of every frame, in order (rewards.size() frames)
  // The most memory one frame takes when built (scene, action and info), bytes; an estimate
  // within a small factor, to choose how many frames to build.
  std::size_t frame_bytes = 0;
  std::optional<EpisodeSummary> summary;
  std::string problem;     // as PartialEpisode
  bool truncated = false;  // as PartialEpisode

  int64_t frames() const { return static_cast<int64_t>(rewards.size()); }
};
EpisodeOutline outline_episode(const std::filesystem::path& file);

}  // namespace tendril
