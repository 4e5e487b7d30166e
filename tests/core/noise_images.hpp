#pragma once
// Garbage in place of a face's photo or ring image, for the leave-one-face-out tests
// (fit/held_out_faces.hpp): uniform noise from a fixed seed, so a test that reads it sees a different
// face every time it is used and the same one on every run.
#include <cstdint>
#include <random>

#include "image/gray_image.hpp"
#include "io/image.hpp"

namespace kerf::testing {

inline Image noisePhoto(int width, int height, std::uint32_t seed = 99) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  Image image(width, height, 3);
  for (float& v : image.pixels) v = value(random);
  return image;
}

inline GrayImage8 noiseRingImage(int width, int height, std::uint32_t seed = 98) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> value(0, 255);
  GrayImage8 image{width, height, {}};
  image.pixels.resize(static_cast<std::size_t>(width) * height);
  for (std::uint8_t& v : image.pixels) v = static_cast<std::uint8_t>(value(random));
  return image;
}

}  // namespace kerf::testing
