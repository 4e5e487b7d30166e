// Where in the ring the dark detail sits (core/fit/ring_band_profile.hpp): synthetic end grain with
// rings 32 px apart (5 mm at 6.4 px/mm), dark pores of 2 px scattered in a chosen part of every ring.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "fit/ring_band_profile.hpp"

using namespace kerf;

namespace {

constexpr int kSize = 128, kRing = 32, kBins = 8;

// The ring phase of row y in kBins parts: rings run along x.
std::vector<std::uint8_t> rowLabels() {
  std::vector<std::uint8_t> labels(kSize * kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      labels[y * kSize + x] = static_cast<std::uint8_t>((y % kRing) * kBins / kRing);
  return labels;
}

// Pale wood with dark 2 x 2 px pores at random places whose ring phase lies in [from, to).
Image poresIn(double from, double to, unsigned seed, int count = 300) {
  Image image(kSize, kSize, 3);
  for (float& v : image.pixels) v = 0.7f;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> column(0, kSize - 2), ring(0, kSize / kRing - 1);
  std::uniform_real_distribution<double> phase(from, to);
  for (int n = 0; n < count; ++n) {
    const int x = column(rng), y = ring(rng) * kRing + static_cast<int>(phase(rng) * kRing);
    for (int dy = 0; dy < 2 && y + dy < kSize; ++dy)
      for (int dx = 0; dx < 2; ++dx)
        for (int c = 0; c < 3; ++c) image.pixel(x + dx, y + dy)[c] = 0.3f;
  }
  return image;
}

double difference(const Image& render, const Image& photo) {
  const std::vector<std::uint8_t> labels = rowLabels();
  return ringBandDifference(ringBandProfile(render, labels, kBins, 6.4),
                            ringBandProfile(photo, labels, kBins, 6.4));
}

}  // namespace

TEST(RingBandProfile, TellsAWideBandOfPoresFromOneRowOfThem) {
  const Image wideBand = poresIn(0.0, 0.3, 1);  // ring-porous: several rows at the start of the earlywood
  // The same band from other pores: close. One row at the ring's start, pores spread over the ring, or
  // the band in the latewood: far.
  const double same = difference(poresIn(0.0, 0.3, 2), wideBand);
  const double oneRow = difference(poresIn(0.0, 0.08, 3), wideBand);
  const double spread = difference(poresIn(0.0, 1.0, 4), wideBand);
  const double late = difference(poresIn(0.6, 0.9, 5), wideBand);
  std::printf("ring band difference: same %.3f, one row %.3f, spread %.3f, latewood %.3f\n", same, oneRow,
              spread, late);
  EXPECT_NEAR(difference(wideBand, wideBand), 0.0, 1e-12);
  EXPECT_LT(same, 0.25);
  EXPECT_GT(oneRow, 2.0 * same);
  EXPECT_GT(spread, 2.0 * same);
  EXPECT_GT(late, 3.0 * same);
}

TEST(RingBandProfile, JudgesWhereNotHowStrong) {
  // Half as many pores in the same band: the same place in the ring, so (nearly) no difference.
  EXPECT_LT(difference(poresIn(0.0, 0.3, 6, 150), poresIn(0.0, 0.3, 1)), 0.3);
  // A render without any dark detail counts as spread evenly; a photo without any judges nothing.
  Image flat(kSize, kSize, 3);
  for (float& v : flat.pixels) v = 0.7f;
  EXPECT_GT(difference(flat, poresIn(0.0, 0.3, 1)), 0.8);
  EXPECT_EQ(difference(poresIn(0.0, 0.3, 1), flat), 0.0);
}
