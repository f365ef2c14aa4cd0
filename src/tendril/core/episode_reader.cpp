#include "tendril/core/episode_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>

#include "tendril/core/crc32c.hpp"
#include "tendril/core/episode_format.hpp"
#include "tendril/core/error.hpp"

namespace tendril {

namespace {

namespace fmt = episode_format;

std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  require(in.good(), "cannot open the episode file", file.string());
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The memory one built frame of `layout` takes, bytes: its numbers as doubles and its names as
// strings, with a generous allowance for each object's own size.
std::size_t frame_bytes(const fmt::Layout& layout) {
  constexpr std::size_t kObject = 96;  // a primitive, a named value, a string's own storage
  std::size_t bytes = sizeof(EpisodeFrame) + sizeof(float) * std::size_t{layout.action_size};
  for (const auto* names : {&layout.info_names, &layout.value_names}) {
    for (const std::string& name : *names) bytes += kObject + name.size();
  }
  for (const fmt::Primitive& p : layout.primitives) {
    bytes += kObject + p.role.size() + sizeof(double) * p.float_count() +
             sizeof(std::array<int, 2>) * p.springs.size();
  }
  return bytes;
}

// Which frames a reading builds: every frame, or those whose indices a sorted list names.
class FrameChoice {
 public:
  FrameChoice() = default;  // every frame
  explicit FrameChoice(const std::vector<int64_t>& frames) : frames_(&frames) {}

  bool keep(int64_t index) {
    if (frames_ == nullptr) return true;
    while (next_ < frames_->size() && (*frames_)[next_] < index) ++next_;
    return next_ < frames_->size() && (*frames_)[next_] == index;
  }

 private:
  const std::vector<int64_t>* frames_ = nullptr;
  std::size_t next_ = 0;
};

// Decodes records in order, keeping the current layout and each primitive's latest data; builds
// the frames `choice` keeps and notes every frame's reward in `outline`.
class Decoder {
 public:
  Decoder(PartialEpisode& out, EpisodeOutline& outline, FrameChoice choice, std::string name)
      : out_(out), outline_(outline), choice_(choice), name_(std::move(name)) {}

  void header(fmt::Cursor& in) {
    const uint32_t version = in.u32();
    if (version > fmt::kVersion) {
      throw Error("format version " + std::to_string(version) + " is newer than this reader's " +
                      std::to_string(fmt::kVersion),
                  name_);
    }
    for (uint32_t n = in.count(8); n > 0; --n) {
      std::string key = in.text();
      out_.episode.metadata.emplace_back(std::move(key), in.text());
    }
  }

  void layout(fmt::Cursor& in) {
    layout_ = fmt::decode_layout(in);
    if (layout_->action_size > static_cast<uint32_t>(std::numeric_limits<int>::max())) {
      throw Error("an action of " + std::to_string(layout_->action_size) + " numbers");
    }
    out_.episode.action_size = static_cast<int>(layout_->action_size);
    latest_.assign(layout_->primitives.size(), {});
    has_data_.assign(layout_->primitives.size(), false);
    outline_.frame_bytes = std::max(outline_.frame_bytes, frame_bytes(*layout_));
  }

  void frame(fmt::Cursor& in) {
    if (!layout_) throw Error("a frame before any layout record");
    const bool keep = choice_.keep(index_);
    EpisodeFrame frame;
    frame.step = in.u32();
    frame.scene.time = in.f64();
    frame.reward = in.f64();
    const uint8_t flags = in.u8();
    frame.terminated = (flags & 1u) != 0;
    frame.truncated = (flags & 2u) != 0;
    // Sizes come from the file: the record must hold the numbers before room is made for them.
    const std::size_t named = layout_->info_names.size() + layout_->value_names.size();
    in.expect(sizeof(float) * (std::size_t{layout_->action_size} + named));
    if (keep) {
      Action action(layout_->action_size);
      bool any_action = false;
      for (uint32_t i = 0; i < layout_->action_size; ++i) {
        action(i) = in.f32();
        any_action = any_action || !std::isnan(action(i));
      }
      if (any_action) frame.action = std::move(action);
      for (const std::string& name : layout_->info_names) frame.info.emplace_back(name, in.f32());
      for (const std::string& name : layout_->value_names) {
        frame.scene.values.emplace_back(name, in.f32());
      }
    } else {
      in.skip(sizeof(float) * (std::size_t{layout_->action_size} + named));
    }
    const std::size_t n = layout_->primitives.size();
    std::vector<uint8_t> changed((n + 7) / 8);
    for (uint8_t& byte : changed) byte = in.u8();
    for (std::size_t i = 0; i < n; ++i) {
      if ((changed[i / 8] >> (i % 8) & 1u) == 0) {
        if (!has_data_[i]) throw Error("primitive " + std::to_string(i) + " never written");
        continue;
      }
      // The latest data of each primitive is held once, however many frames reuse it.
      std::vector<float>& data = latest_[i];
      in.expect(sizeof(float) * layout_->primitives[i].float_count());
      data.resize(layout_->primitives[i].float_count());
      for (float& value : data) value = in.f32();
      has_data_[i] = true;
    }
    if (!in.done()) throw Error("a frame record longer than its layout");
    outline_.rewards.push_back(frame.reward);
    ++index_;
    if (!keep) return;
    fmt::fill_scene(*layout_, latest_, frame.scene);
    out_.episode.frames.push_back(std::move(frame));
  }

  void end(fmt::Cursor& in) {
    EpisodeSummary summary;
    summary.steps = in.u32();
    summary.episode_return = in.f64();
    const uint8_t flags = in.u8();
    summary.terminated = (flags & 1u) != 0;
    summary.truncated = (flags & 2u) != 0;
    out_.episode.summary = summary;
  }

 private:
  PartialEpisode& out_;
  EpisodeOutline& outline_;
  FrameChoice choice_;
  std::string name_;
  std::optional<fmt::Layout> layout_;
  std::vector<std::vector<float>> latest_;
  std::vector<bool> has_data_;
  int64_t index_ = 0;
};

PartialEpisode read(const std::filesystem::path& file, FrameChoice choice,
                    EpisodeOutline& outline) {
  const std::string bytes = read_bytes(file);
  const std::string name = file.string();
  if (bytes.size() < fmt::kMagic.size() || bytes.compare(0, fmt::kMagic.size(), fmt::kMagic) != 0) {
    throw Error("not an episode file (no 'tendril-episode' magic)", name);
  }
  PartialEpisode result;
  Decoder decoder(result, outline, choice, name);
  std::size_t position = fmt::kMagic.size();
  bool has_header = false;
  auto stop = [&](const std::string& problem, bool truncated) {
    result.problem = problem + " at byte " + std::to_string(position);
    result.truncated = truncated;
  };
  while (true) {
    if (result.episode.summary) {
      if (position != bytes.size()) stop("bytes after the end record", false);
      break;
    }
    const std::size_t left = bytes.size() - position;
    if (left == 0) {
      stop("no end record (the recording is unfinished or was cut off)", true);
      break;
    }
    if (left < 5) {
      stop("the file ends inside a record", true);
      break;
    }
    const auto tag = static_cast<fmt::Tag>(static_cast<uint8_t>(bytes[position]));
    uint32_t length;
    std::memcpy(&length, bytes.data() + position + 1, sizeof length);
    if (left < fmt::kRecordOverhead + std::size_t{length}) {
      stop("the file ends inside a record", true);
      break;
    }
    uint32_t stored;
    std::memcpy(&stored, bytes.data() + position + 5 + length, sizeof stored);
    if (crc32(bytes.data() + position, 5 + std::size_t{length}) != stored) {
      stop("checksum mismatch in a record", false);
      break;
    }
    fmt::Cursor in(std::string_view(bytes).substr(position + 5, length),
                   name + " (record at byte " + std::to_string(position) + ")");
    try {
      if (!has_header && tag != fmt::Tag::kHeader) throw Error("the first record is no header");
      switch (tag) {
        case fmt::Tag::kHeader:
          if (has_header) throw Error("a second header record");
          decoder.header(in);
          has_header = true;
          break;
        case fmt::Tag::kLayout:
          decoder.layout(in);
          break;
        case fmt::Tag::kFrame:
          decoder.frame(in);
          break;
        case fmt::Tag::kEnd:
          decoder.end(in);
          break;
        default:
          throw Error("unknown record tag " + std::to_string(static_cast<int>(tag)));
      }
    } catch (const Error& e) {
      if (!has_header) throw Error("unreadable header: " + e.what_wrong(), name);
      stop(e.what_wrong(), false);
      break;
    }
    position += fmt::kRecordOverhead + length;
  }
  if (!has_header) throw Error("unreadable header: " + result.problem, name);
  return result;
}

}  // namespace

Episode read_episode(const std::filesystem::path& file) {
  EpisodeOutline outline;
  PartialEpisode partial = read(file, FrameChoice(), outline);
  if (!partial.problem.empty()) throw Error(partial.problem, file.string());
  return std::move(partial.episode);
}

PartialEpisode read_partial_episode(const std::filesystem::path& file) {
  EpisodeOutline outline;
  return read(file, FrameChoice(), outline);
}

PartialEpisode read_partial_episode(const std::filesystem::path& file,
                                    const std::vector<int64_t>& frames) {
  EpisodeOutline outline;
  return read(file, FrameChoice(frames), outline);
}

EpisodeOutline outline_episode(const std::filesystem::path& file) {
  static const std::vector<int64_t> none;
  EpisodeOutline outline;
  PartialEpisode partial = read(file, FrameChoice(none), outline);
  outline.metadata = std::move(partial.episode.metadata);
  outline.action_size = partial.episode.action_size;
  outline.summary = partial.episode.summary;
  outline.problem = std::move(partial.problem);
  outline.truncated = partial.truncated;
  return outline;
}

std::string Episode::meta(const std::string& key, const std::string& fallback) const {
  for (const auto& [name, value] : metadata) {
    if (name == key) return value;
  }
  return fallback;
}

}  // namespace tendril
