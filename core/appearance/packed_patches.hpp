#pragma once
// The patch distance of the guided synthesis (appearance/guided_synthesis.hpp), in a form that runs fast:
//  - every pixel's colour and guidance features packed into a few 4-float vectors, and only the guidance
//    channels that are not zero everywhere (the year's weight is 0 by default), so the distance is a few
//    vector subtractions and multiply-adds per sample, in a fixed order (the same sum on every thread);
//  - the patch turned by an angle quantised to kAngleBins steps, whose samples' offsets are looked up in
//    a table made once per image, instead of a cosine, a sine and a rounding per sample (Barnes et al.
//    2010, "The generalized PatchMatch", Sec. 3.1, search rotations the same way);
//  - images padded with replicated border pixels, so no sample is clamped;
//  - the sum stops once it exceeds the best distance so far (it is only compared with it).
// Float4 is the GCC/Clang vector extension: SSE on x86-64, NEON on ARM, plain code elsewhere.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace kerf {

using Float4 = float __attribute__((vector_size(16)));
// The exemplars' pixels in 16-bit fixed point: half the memory of floats, and the random candidates of
// PatchMatch read them from memory rather than cache (the distance waits on those reads).
using Short4 = std::int16_t __attribute__((vector_size(8)));

// Four 16-bit lanes to floats: on x86-64 three SSE2 instructions (the compiler's own conversion goes lane
// by lane there).
inline Float4 toFloat4(Short4 lanes) {
#if defined(__SSE2__)
  __m128i x = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(&lanes));
  x = _mm_srai_epi32(_mm_unpacklo_epi16(x, x), 16);
  return reinterpret_cast<Float4>(_mm_cvtepi32_ps(x));
#else
  return __builtin_convertvector(lanes, Float4);
#endif
}

inline constexpr int kAngleBins = 256;  // 1.4 degrees: at a patch's corner, 0.1 px
std::uint8_t angleBin(float radians);
float binAngle(int bin);  // the bin's centre, radians

// An image of packed pixels: `chunks` lane groups (Float4 or Short4) each; chunk 0 is the colour times
// the colour weight and a zero, the others the kept guidance channels, zero-padded, everything times
// `scale` (for Short4: rounded and clamped to 16 bits). `pad` pixels of the nearest border pixel on every
// side.
template <class Lanes>
struct PackedImage {
  int width = 0, height = 0, pad = 0, chunks = 0;
  int rowPixels = 0;  // width + 2 pad
  std::vector<Lanes> data;

  PackedImage() = default;
  PackedImage(int width, int height, int pad, int chunks);
  // Where pixel (x, y)'s first chunk is, in lane groups from data's start; x and y may reach into the pad.
  std::ptrdiff_t index(int x, int y) const {
    return (static_cast<std::ptrdiff_t>(y + pad) * rowPixels + (x + pad)) * chunks;
  }
  Lanes* at(int x, int y) { return &data[static_cast<std::size_t>(index(x, y))]; }
  const Lanes* at(int x, int y) const { return &data[static_cast<std::size_t>(index(x, y))]; }
  // The colour (chunk 0) of every pixel, times `weight` and the scale; rgb: 3 floats per pixel, row-major.
  void setColours(const float* rgb, float weight, float scale);
  // The guidance features of every pixel (features: `stride` floats per pixel), only the `kept` channels,
  // times the scale.
  void setFeatures(const float* features, int stride, const std::vector<int>& kept, float scale);
  // The pad from the border pixels (after setting colours or features).
  void fillPad();
};

// The chunks a pixel needs for `keptChannels` guidance channels.
inline int packedChunks(int keptChannels) {
  return 1 + (keptChannels + 3) / 4;
}

// A patch's samples: offsets (dx, dy) on a grid of `step` pixels over [-radius, radius]^2, row by row,
// and each turned by every angle bin (the rotation of the synthesis: (dx, dy) goes to (c dx + s dy,
// -s dx + c dy)) and rounded to the nearest pixel from a patch centre at each of phases x phases
// sub-pixel positions: a sample of the patch centred at q is at floor(q) + turned(bin, phase of q's
// fraction), within half a pixel plus 1 / (2 phases) of where it belongs.
class PatchSamples {
 public:
  PatchSamples(int radius, int step, int phases);
  int count() const { return static_cast<int>(dx_.size()); }
  int perRow() const { return perRow_; }
  int dx(int k) const { return dx_[k]; }
  int dy(int k) const { return dy_[k]; }
  // The whole pixel at or below q and the sub-pixel phase of q's fraction.
  int phase(float q, int& whole) const {
    const float floor = std::floor(q);
    whole = static_cast<int>(floor);
    return std::min(static_cast<int>((q - floor) * phases_), phases_ - 1);
  }
  // (x, y) pairs of every sample, turned by `bin`, for a centre at sub-pixel phases (phaseX, phaseY).
  const std::int8_t* turned(int bin, int phaseX, int phaseY) const {
    return &turned_[((static_cast<std::size_t>(bin) * phases_ + phaseY) * phases_ + phaseX) * count() * 2];
  }
  // The samples' (unturned) offsets in Float4 in `image`.
  std::vector<int> offsets(const PackedImage<Float4>& image) const;

 private:
  int perRow_ = 0, phases_ = 1;
  std::vector<int> dx_, dy_;
  std::vector<std::int8_t> turned_;
};

// The sum of squared differences between the patch at target pixel `t` (its samples at tOffsets, in
// Float4) and the turned patch at exemplar pixel `e` (its samples at the (x, y) pairs `turned`, in an
// image whose rows are `eRow` Short4 long), chunks from First (0: with the colour, 1: the guidance alone)
// to Chunks - 1. Checked after each row of samples: once the sum reaches `bound`, the rest is skipped
// and what was summed so far is returned.
template <int Chunks, int First>
float patchDistance(const Float4* t, const int* tOffsets, const Short4* e, const std::int8_t* turned,
                    int eRow, int count, int perRow, float bound) {
  Float4 acc = {0.0f, 0.0f, 0.0f, 0.0f};
  float sum = 0.0f;
  for (int k = 0; k < count;) {
    for (const int rowEnd = k + perRow; k < rowEnd; ++k) {
      const Float4* a = t + tOffsets[k];
      const Short4* b = e + turned[2 * k + 1] * eRow + turned[2 * k] * Chunks;
      for (int c = First; c < Chunks; ++c) {
        const Float4 d = a[c] - toFloat4(b[c]);
        acc += d * d;
      }
    }
    sum = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    if (sum >= bound) return sum;
  }
  return sum;
}

// patchDistance for an image's chunk count (2, 3 or 4), with the colour or not: chosen once per pass.
using PatchDistanceFunction = float (*)(const Float4* t, const int* tOffsets, const Short4* e,
                                        const std::int8_t* turned, int eRow, int count, int perRow,
                                        float bound);
PatchDistanceFunction patchDistanceFor(int chunks, bool withColour);

}  // namespace kerf
