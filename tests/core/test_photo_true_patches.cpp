// The fast patch distance of the photo-true synthesis (appearance/packed_patches.hpp) against a plain
// reference on random data: the same sum, the turned samples where the rotation puts them, the early
// stop only above the bound, the colour left out when asked.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "appearance/packed_patches.hpp"
#include "util/split_mix.hpp"

using namespace kerf;

namespace {

constexpr int kRadius = 5, kStep = 2, kPhases = 4;

// Values as the fixed point holds them: up to 2 (a weighted feature) in steps of 1/4096.
PackedImage<Float4> randomTarget(int w, int h, int pad, int chunks, SplitMix& random) {
  PackedImage<Float4> image(w, h, pad, chunks);
  for (Float4& v : image.data)
    for (int i = 0; i < 4; ++i) v[i] = (random.uniform() * 2.0f - 1.0f) * 8192.0f;
  return image;
}

PackedImage<Short4> randomExemplar(int w, int h, int chunks, SplitMix& random) {
  PackedImage<Short4> image(w, h, 0, chunks);
  for (Short4& v : image.data)
    for (int i = 0; i < 4; ++i) v[i] = static_cast<std::int16_t>(random.below(16385) - 8192);
  return image;
}

// The plain sum over every sample and chunk, in double, at the samples the table gives.
double referenceDistance(const PackedImage<Float4>& target, int px, int py,
                         const PackedImage<Short4>& exemplar, int ix, int iy, const PatchSamples& samples,
                         const std::int8_t* turned, int first) {
  double sum = 0.0;
  for (int k = 0; k < samples.count(); ++k) {
    const Float4* a = target.at(px + samples.dx(k), py + samples.dy(k));
    const Short4* b = exemplar.at(ix + turned[2 * k], iy + turned[2 * k + 1]);
    for (int c = first; c < target.chunks; ++c)
      for (int i = 0; i < 4; ++i) sum += double(a[c][i] - b[c][i]) * double(a[c][i] - b[c][i]);
  }
  return sum;
}

}  // namespace

TEST(PhotoTruePatchDistance, SameSumAsAPlainLoop) {
  SplitMix random{11};
  const PatchSamples samples(kRadius, kStep, kPhases);
  for (int chunks : {2, 3, 4}) {
    const PackedImage<Float4> target = randomTarget(30, 20, kRadius, chunks, random);
    const PackedImage<Short4> exemplar = randomExemplar(40, 40, chunks, random);
    for (int trial = 0; trial < 200; ++trial) {
      const int px = random.below(30), py = random.below(20);
      const float qx = 10.0f + 20.0f * random.uniform(), qy = 10.0f + 20.0f * random.uniform();
      const int bin = random.below(kAngleBins);
      int ix, iy;
      const int phaseX = samples.phase(qx, ix), phaseY = samples.phase(qy, iy);
      const std::int8_t* turned = samples.turned(bin, phaseX, phaseY);
      const std::vector<int> offsets = samples.offsets(target);
      for (int first : {0, 1}) {
        const double reference = referenceDistance(target, px, py, exemplar, ix, iy, samples, turned, first);
        const float fast = patchDistanceFor(chunks, first == 0)(
            target.at(px, py), offsets.data(), exemplar.at(ix, iy), turned, exemplar.rowPixels * chunks,
            samples.count(), samples.perRow(), std::numeric_limits<float>::max());
        EXPECT_NEAR(fast, reference, 1e-4 * reference) << "chunks " << chunks << ", first " << first;
        // Stopped early only once past the bound: below it the whole sum, above it at least the bound.
        const float bound = static_cast<float>(reference) * (trial % 2 == 0 ? 0.5f : 1.5f);
        const float bounded = patchDistanceFor(chunks, first == 0)(
            target.at(px, py), offsets.data(), exemplar.at(ix, iy), turned, exemplar.rowPixels * chunks,
            samples.count(), samples.perRow(), bound);
        if (reference < bound)
          EXPECT_NEAR(bounded, reference, 1e-4 * reference);
        else
          EXPECT_GE(bounded, bound);
      }
    }
  }
}

TEST(PhotoTruePatchDistance, TurnedSamplesLieWhereTheRotationPutsThem) {
  SplitMix random{12};
  const PatchSamples samples(kRadius, kStep, kPhases);
  // Half a pixel of rounding, half a phase, and the angle's quantisation at the patch's corner.
  const float tolerance =
      0.5f + 0.5f / kPhases + kRadius * std::sqrt(2.0f) * std::numbers::pi_v<float> / kAngleBins + 1e-4f;
  for (int trial = 0; trial < 500; ++trial) {
    const float angle = (random.uniform() * 4.0f - 2.0f) * std::numbers::pi_v<float>;
    const float qx = 50.0f * random.uniform(), qy = 50.0f * random.uniform();
    int ix, iy;
    const int phaseX = samples.phase(qx, ix), phaseY = samples.phase(qy, iy);
    const std::int8_t* turned = samples.turned(angleBin(angle), phaseX, phaseY);
    const float c = std::cos(angle), s = std::sin(angle);
    for (int k = 0; k < samples.count(); ++k) {
      const float dx = float(samples.dx(k)), dy = float(samples.dy(k));
      EXPECT_NEAR(ix + turned[2 * k], qx + c * dx + s * dy, tolerance);
      EXPECT_NEAR(iy + turned[2 * k + 1], qy - s * dx + c * dy, tolerance);
    }
  }
}

TEST(PhotoTruePatchDistance, AngleBinsWrapAround) {
  EXPECT_EQ(angleBin(0.0f), 0);
  EXPECT_EQ(angleBin(2.0f * std::numbers::pi_v<float>), 0);
  EXPECT_EQ(angleBin(-std::numbers::pi_v<float> / 2), 3 * kAngleBins / 4);
  EXPECT_NEAR(binAngle(angleBin(1.0f)), 1.0f, std::numbers::pi_v<float> / kAngleBins);
  // A difference of bins is the bin of the difference (the synthesis subtracts them modulo 256).
  EXPECT_EQ(static_cast<std::uint8_t>(angleBin(0.3f) - angleBin(2.9f)), angleBin(0.3f - 2.9f));
}
