#pragma once
// A plain float image (values 0..1, interleaved channels): the pixels only. Reading and writing image
// files is io/image.hpp's job, so the renderers and the ring detector need no file formats.
#include <cstddef>
#include <vector>

namespace kerf {

struct Image {
  int width = 0, height = 0, channels = 3;
  std::vector<float> pixels;  // row-major, top row first, `channels` floats per pixel

  Image() = default;
  Image(int w, int h, int c)
      : width(w), height(h), channels(c), pixels(static_cast<std::size_t>(w) * h * c, 0.0f) {}
  float* pixel(int x, int y) { return &pixels[(static_cast<std::size_t>(y) * width + x) * channels]; }
  const float* pixel(int x, int y) const {
    return &pixels[(static_cast<std::size_t>(y) * width + x) * channels];
  }
  bool empty() const { return pixels.empty(); }
};

}  // namespace kerf
