#include "appearance/packed_patches.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/error.hpp"

namespace kerf {

namespace {
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
}

std::uint8_t angleBin(float radians) {
  const long bin = std::lround(radians / kTwoPi * kAngleBins);
  return static_cast<std::uint8_t>(((bin % kAngleBins) + kAngleBins) % kAngleBins);
}

float binAngle(int bin) {
  return kTwoPi * static_cast<float>(bin) / kAngleBins;
}

namespace {

void store(Float4& lanes, int lane, float value) {
  lanes[lane] = value;
}

void store(Short4& lanes, int lane, float value) {
  lanes[lane] = static_cast<std::int16_t>(std::clamp(std::lround(value), -32767L, 32767L));
}

}  // namespace

template <class Lanes>
PackedImage<Lanes>::PackedImage(int width_, int height_, int pad_, int chunks_)
    : width(width_), height(height_), pad(pad_), chunks(chunks_), rowPixels(width_ + 2 * pad_) {
  data.assign(static_cast<std::size_t>(rowPixels) * (height + 2 * pad) * chunks, Lanes{0, 0, 0, 0});
}

template <class Lanes>
void PackedImage<Lanes>::setColours(const float* rgb, float weight, float scale) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* c = rgb + (static_cast<std::size_t>(y) * width + x) * 3;
      Lanes& lanes = *at(x, y);
      for (int i = 0; i < 3; ++i) store(lanes, i, weight * scale * c[i]);
      store(lanes, 3, 0.0f);
    }
}

template <class Lanes>
void PackedImage<Lanes>::setFeatures(const float* features, int stride, const std::vector<int>& kept,
                                     float scale) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* f = features + (static_cast<std::size_t>(y) * width + x) * stride;
      Lanes* out = at(x, y) + 1;
      for (std::size_t i = 0; i < kept.size(); ++i)
        store(out[i / 4], static_cast<int>(i % 4), scale * f[kept[i]]);
    }
}

template <class Lanes>
void PackedImage<Lanes>::fillPad() {
  if (pad == 0) return;
  for (int y = -pad; y < height + pad; ++y)
    for (int x = -pad; x < width + pad; ++x) {
      if (x >= 0 && x < width && y >= 0 && y < height) continue;
      const Lanes* from = at(std::clamp(x, 0, width - 1), std::clamp(y, 0, height - 1));
      std::copy_n(from, chunks, at(x, y));
    }
}

template struct PackedImage<Float4>;
template struct PackedImage<Short4>;

PatchSamples::PatchSamples(int radius, int step, int phases) : phases_(phases) {
  for (int dy = -radius; dy <= radius; dy += step)
    for (int dx = -radius; dx <= radius; dx += step) {
      dx_.push_back(dx);
      dy_.push_back(dy);
    }
  perRow_ = (2 * radius) / step + 1;
  if (radius * 1.5f + 1.0f > 127.0f || phases < 1)
    throw InputError("photo-true appearance: patches too large or no sub-pixel phase");
  turned_.resize(static_cast<std::size_t>(kAngleBins) * phases * phases * count() * 2);
  for (int bin = 0; bin < kAngleBins; ++bin) {
    const float c = std::cos(binAngle(bin)), s = std::sin(binAngle(bin));
    for (int py = 0; py < phases; ++py)
      for (int px = 0; px < phases; ++px) {
        // The phase's centre: where in its pixel the patch centre is taken to be.
        const float fx = (px + 0.5f) / phases, fy = (py + 0.5f) / phases;
        std::int8_t* out =
            &turned_[((static_cast<std::size_t>(bin) * phases + py) * phases + px) * count() * 2];
        for (int k = 0; k < count(); ++k) {
          out[2 * k] = static_cast<std::int8_t>(std::floor(fx + c * dx_[k] + s * dy_[k] + 0.5f));
          out[2 * k + 1] = static_cast<std::int8_t>(std::floor(fy - s * dx_[k] + c * dy_[k] + 0.5f));
        }
      }
  }
}

std::vector<int> PatchSamples::offsets(const PackedImage<Float4>& image) const {
  std::vector<int> out(dx_.size());
  for (int k = 0; k < count(); ++k)
    out[k] = static_cast<int>(image.index(dx_[k], dy_[k]) - image.index(0, 0));
  return out;
}

PatchDistanceFunction patchDistanceFor(int chunks, bool withColour) {
  switch (chunks) {
    case 2:
      return withColour ? &patchDistance<2, 0> : &patchDistance<2, 1>;
    case 3:
      return withColour ? &patchDistance<3, 0> : &patchDistance<3, 1>;
    case 4:
      return withColour ? &patchDistance<4, 0> : &patchDistance<4, 1>;
    default:
      throw InputError("photo-true appearance: unsupported packed pixel size");
  }
}

}  // namespace kerf
