#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace tendril::render {

using Colour = std::array<uint8_t, 3>;  // sRGB

// The colour a scene primitive is drawn in, by its role — the dashboard's palette
// (web/src/scene3d.js): arm and rod orange, target red, goal green, obstacles and walls grey,
// ground sage, paths and references blue; any other role a hue of its own from its name.
Colour role_colour(const std::string& role);

}  // namespace tendril::render
