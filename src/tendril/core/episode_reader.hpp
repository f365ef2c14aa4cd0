#pragma once

#include <filesystem>
#include <string>

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

}  // namespace tendril
