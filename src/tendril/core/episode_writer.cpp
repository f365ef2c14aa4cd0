#include "tendril/core/episode_writer.hpp"

#include <cmath>
#include <limits>

#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"

namespace tendril {

namespace fmt = episode_format;

EpisodeWriter::EpisodeWriter(std::filesystem::path file, const EpisodeMetadata& metadata,
                             int action_size)
    : file_(std::move(file)), action_size_(static_cast<uint32_t>(action_size)) {
  require(action_size >= 0, "negative action size", file_.string());
  require(!std::filesystem::exists(file_), "exists already (nothing is overwritten)",
          file_.string());
  out_.open(file_, std::ios::binary);
  require(out_.good(), "cannot create the episode file", file_.string());
  out_.write(fmt::kMagic.data(), static_cast<std::streamsize>(fmt::kMagic.size()));
  fmt::Bytes header;
  header.u32(fmt::kVersion);
  header.u32(static_cast<uint32_t>(metadata.size()));
  for (const auto& [key, value] : metadata) header.text(key), header.text(value);
  write_record(fmt::Tag::kHeader, header.str());
}

EpisodeWriter::~EpisodeWriter() {
  if (out_.is_open()) out_.close();  // without an end record: an incomplete recording
}

void EpisodeWriter::write(const EpisodeFrame& frame) {
  require(!finished_, "write after finish", file_.string());
  require(frame.action.size() == 0 || frame.action.size() == action_size_,
          "a frame's action has " + std::to_string(frame.action.size()) + " values, expected " +
              std::to_string(action_size_),
          file_.string());
  std::vector<std::string> info_names;
  for (const auto& entry : frame.info) info_names.push_back(entry.first);
  fmt::Layout layout = fmt::layout_of(frame.scene, std::move(info_names), action_size_);
  if (!layout_ || !(*layout_ == layout)) {
    fmt::Bytes record;
    fmt::encode_layout(layout, record);
    write_record(fmt::Tag::kLayout, record.str());
    layout_ = std::move(layout);
    previous_.assign(layout_->primitives.size(), {});  // every primitive is written in full
  }

  fmt::Bytes record;
  record.u32(static_cast<uint32_t>(frame.step));
  record.f64(frame.scene.time);
  record.f64(frame.reward);
  record.u8((frame.terminated ? 1 : 0) | (frame.truncated ? 2 : 0));
  for (uint32_t i = 0; i < action_size_; ++i) {
    record.f32(frame.action.size() == 0 ? std::numeric_limits<float>::quiet_NaN()
                                        : frame.action(i));
  }
  for (const auto& entry : frame.info) record.f32(static_cast<float>(entry.second));
  for (const auto& value : frame.scene.values) record.f32(static_cast<float>(value.second));

  // One bit per primitive: set when its data follows (it changed since the previous frame).
  std::vector<std::vector<float>> data = fmt::primitive_data(frame.scene);
  std::vector<uint8_t> changed((data.size() + 7) / 8, 0);
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (data[i] != previous_[i]) changed[i / 8] |= static_cast<uint8_t>(1u << (i % 8));
  }
  record.raw(changed.data(), changed.size());
  for (std::size_t i = 0; i < data.size(); ++i) {
    if ((changed[i / 8] >> (i % 8) & 1u) == 0) continue;
    record.raw(data[i].data(), data[i].size() * sizeof(float));
    previous_[i] = std::move(data[i]);
  }
  write_record(fmt::Tag::kFrame, record.str());

  ++frames_;
  summary_.steps = frame.step;
  summary_.episode_return += frame.reward;
  summary_.terminated = frame.terminated;
  summary_.truncated = frame.truncated;
}

EpisodeSummary EpisodeWriter::finish() {
  require(!finished_, "finish called twice", file_.string());
  fmt::Bytes record;
  record.u32(static_cast<uint32_t>(summary_.steps));
  record.f64(summary_.episode_return);
  record.u8((summary_.terminated ? 1 : 0) | (summary_.truncated ? 2 : 0));
  write_record(fmt::Tag::kEnd, record.str());
  out_.close();
  require(!out_.fail(), "writing the episode file failed", file_.string());
  finished_ = true;
  return summary_;
}

void EpisodeWriter::write_record(fmt::Tag tag, const std::string& payload) {
  fmt::Bytes framed;
  framed.u8(static_cast<uint8_t>(tag));
  framed.u32(static_cast<uint32_t>(payload.size()));
  framed.raw(payload.data(), payload.size());
  const uint32_t check = crc32(framed.str().data(), framed.str().size());
  framed.u32(check);
  out_.write(framed.str().data(), static_cast<std::streamsize>(framed.str().size()));
  require(out_.good(), "writing the episode file failed", file_.string());
}

}  // namespace tendril
