#include "tendril/render/role_colours.hpp"

#include <cmath>
#include <map>

namespace tendril::render {

namespace {

Colour hex(uint32_t value) {
  return {static_cast<uint8_t>(value >> 16), static_cast<uint8_t>(value >> 8),
          static_cast<uint8_t>(value)};
}

// HSL → RGB with saturation 0.55 and lightness 0.5, as the dashboard colours unknown roles.
Colour from_hue(double hue) {
  const double s = 0.55, l = 0.5;
  const double c = (1.0 - std::abs(2.0 * l - 1.0)) * s;
  const double h = hue * 6.0;
  const double x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  if (h < 1) {
    r = c;
    g = x;
  } else if (h < 2) {
    r = x;
    g = c;
  } else if (h < 3) {
    g = c;
    b = x;
  } else if (h < 4) {
    g = x;
    b = c;
  } else if (h < 5) {
    r = x;
    b = c;
  } else {
    r = c;
    b = x;
  }
  const double m = l - 0.5 * c;
  const auto byte = [&](double v) { return static_cast<uint8_t>(std::lround(255.0 * (v + m))); };
  return {byte(r), byte(g), byte(b)};
}

}  // namespace

Colour role_colour(const std::string& role) {
  static const std::map<std::string, uint32_t> colours = {
      {"arm", 0xe07b39},    {"rod", 0xe07b39},      {"target", 0xd62728},
      {"goal", 0x2ca02c},   {"obstacle", 0x6c7a89}, {"wall", 0x6c7a89},
      {"ground", 0xb8c4a8}, {"path", 0x1f77b4},     {"reference", 0x1f77b4}};
  const auto found = colours.find(role);
  if (found != colours.end()) return hex(found->second);
  int32_t hash = 0;
  for (const char c : role)
    hash = static_cast<int32_t>(static_cast<uint32_t>(hash) * 31u + static_cast<uint8_t>(c));
  return from_hue(static_cast<double>(static_cast<uint32_t>(hash) % 360) / 360.0);
}

}  // namespace tendril::render
