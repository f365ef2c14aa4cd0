#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "tendril/core/episode.hpp"
#include "tendril/core/episode_format.hpp"

namespace tendril {

// Writes one episode file (docs/episode_format.md) frame by frame: a header with the metadata,
// a layout record whenever the scene's structure changes, one record per frame holding only the
// primitives that changed since the previous frame (obstacles are stored once), and an end
// record with the summary. Every record carries a CRC-32. A file without its end record (the
// writer was destroyed before `finish`, the process died) reads back as incomplete.
class EpisodeWriter {
 public:
  // Raises Error if `file` exists (nothing is overwritten) or cannot be created.
  EpisodeWriter(std::filesystem::path file, const EpisodeMetadata& metadata, int action_size);
  ~EpisodeWriter();
  EpisodeWriter(const EpisodeWriter&) = delete;
  EpisodeWriter& operator=(const EpisodeWriter&) = delete;

  // Appends a frame; its action must be empty or of the action size. Raises Error after finish.
  void write(const EpisodeFrame& frame);
  // Writes the end record and closes the file; returns what it states.
  EpisodeSummary finish();

  const std::filesystem::path& file() const { return file_; }
  int64_t frames() const { return frames_; }

 private:
  void write_record(episode_format::Tag tag, const std::string& payload);

  std::filesystem::path file_;
  std::ofstream out_;
  uint32_t action_size_;
  std::optional<episode_format::Layout> layout_;
  std::vector<std::vector<float>> previous_;  // each primitive's data in the previous frame
  EpisodeSummary summary_;
  int64_t frames_ = 0;
  bool finished_ = false;
};

}  // namespace tendril
