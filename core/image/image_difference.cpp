#include "image/image_difference.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "util/error.hpp"

namespace kerf {

ImageDifference compareImages(const Image& a, const Image& b, float tolerance) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
    throw InputError("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                     "x" + std::to_string(a.channels) + " vs " + std::to_string(b.width) + "x" +
                     std::to_string(b.height) + "x" + std::to_string(b.channels));
  }
  ImageDifference d;
  std::size_t over = 0;
  const std::size_t count = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t i = 0; i < count; ++i) {
    float worst = 0;
    for (int c = 0; c < a.channels; ++c) {
      const float e = std::abs(a.pixels[i * a.channels + c] - b.pixels[i * a.channels + c]);
      d.meanAbs += e;
      worst = std::max(worst, e);
    }
    if (worst > tolerance) ++over;
  }
  d.meanAbs /= static_cast<double>(count * a.channels);
  d.shareOverTolerance = static_cast<double>(over) / count;
  return d;
}

}  // namespace kerf
