#pragma once
// An 8-bit single-channel image (ring-localization images, Mokume annotation and knot images): the
// values those files hold, without a round trip through floats.
#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace kerf {

struct GrayImage8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // row-major, top row first
  std::uint8_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  bool empty() const { return pixels.empty(); }
};

// The first channel of `image` (0..1) quantised to 0..255.
GrayImage8 toGray8(const Image& image);

}  // namespace kerf
