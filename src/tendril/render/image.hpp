#pragma once

#include <cstdint>
#include <vector>

namespace tendril::render {

// An 8-bit RGB picture, rows from the top, three bytes per pixel (NumPy's height × width × 3
// uint8 layout, what Gymnasium's rgb_array and ffmpeg's rgb24 take).
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;

  void resize(int new_width, int new_height) {
    width = new_width;
    height = new_height;
    rgb.assign(static_cast<std::size_t>(width) * height * 3, 0);
  }
  const uint8_t* pixel(int x, int y) const {
    return rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x);
  }
};

}  // namespace tendril::render
