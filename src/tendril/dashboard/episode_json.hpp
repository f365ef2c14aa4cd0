#pragma once

#include <string>

#include "tendril/core/episode_reader.hpp"

namespace tendril::dashboard {

// An episode as the page's replay reads it (docs/dashboard.md): metadata, the summary or the
// problem that stopped reading, and at most `max_frames` frames — every k-th, and always the last
// — each with its scene in the lab frame (metres). A lattice's springs, which rarely change, are
// listed once in "springs" and referred to by index.
std::string episode_json(const PartialEpisode& episode, int max_frames);

}  // namespace tendril::dashboard
