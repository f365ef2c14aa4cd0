#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace tendril::dashboard {

// An episode file as the page's replay reads it (docs/dashboard.md): metadata, the summary or the
// problem that stopped reading, and at most `max_frames` frames — every k-th, and always the last
// — each with its scene in the lab frame (metres). A lattice's springs, which rarely change, are
// listed once in "springs" and referred to by index. Fewer frames are sent (a larger k) when
// `max_frames` of them would take more than about `max_bytes` of memory to build, so that a small
// file whose frames repeat large primitives cannot make the answer huge; the first and the last
// frame are always sent. Raises Error when the file is not an episode file.
std::string episode_json(const std::filesystem::path& file, int max_frames, std::size_t max_bytes);

}  // namespace tendril::dashboard
