#pragma once
// Test fixture shared by the fitting tests: the ring-localization image a perfect detector would give
// for one face of a known field, I = ((cos(2 pi (g - offset)) + 1) / 2)^10 (Mokume Eq. 1) at pixel centres.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "field/growth_field.hpp"
#include "fit/iso_contours.hpp"
#include "geometry/block.hpp"

namespace kerf::testing {

// The same for any field g (e.g. a growth field with knots merged in).
template <typename Field>
inline GrayImage8 renderRingImageOf(const Field& g, const Block& block, FaceId face, int px, float offset) {
  GrayImage8 im;
  im.width = im.height = px;
  im.pixels.resize(static_cast<std::size_t>(px) * px);
  for (int y = 0; y < px; ++y)
    for (int x = 0; x < px; ++x) {
      const double v = g(block.pixelCenter(face, x, y, {px, px}));
      const double i = std::pow((std::cos(2 * std::numbers::pi * (v - offset)) + 1) / 2, 10.0);
      im.pixels[static_cast<std::size_t>(y) * px + x] = static_cast<std::uint8_t>(std::lround(255 * i));
    }
  return im;
}

inline GrayImage8 renderRingImage(const GrowthField& field, const Block& block, FaceId face, int px,
                                  float offset) {
  GrayImage8 im;
  im.width = im.height = px;
  im.pixels.resize(static_cast<std::size_t>(px) * px);
  for (int y = 0; y < px; ++y)
    for (int x = 0; x < px; ++x) {
      const double g = field.evaluate(block.pixelCenter(face, x, y, {px, px}));
      const double i = std::pow((std::cos(2 * std::numbers::pi * (g - offset)) + 1) / 2, 10.0);
      im.pixels[static_cast<std::size_t>(y) * px + x] = static_cast<std::uint8_t>(std::lround(255 * i));
    }
  return im;
}

}  // namespace kerf::testing
