#include "image/gray_image.hpp"

#include <algorithm>
#include <cmath>

namespace kerf {

GrayImage8 toGray8(const Image& image) {
  GrayImage8 gray;
  gray.width = image.width;
  gray.height = image.height;
  gray.pixels.resize(static_cast<std::size_t>(image.width) * image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      gray.pixels[static_cast<std::size_t>(y) * image.width + x] =
          static_cast<std::uint8_t>(std::lround(std::clamp(image.pixel(x, y)[0], 0.0f, 1.0f) * 255.0f));
  return gray;
}

}  // namespace kerf
