// What a woodworker sees first (texture/grain_view.hpp): grain direction agreement and contrast against
// a photo, on images whose answer is known analytically, and in the texture objective on the synthetic
// block: a render whose detail is washed out scores worse there than the true wood with other pores.
// Scales follow the image's px/mm (the synthetic photos have 12.8, the yardstick's 6.4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "texture/grain_view.hpp"
#include "texture/texture_objective.hpp"
#include "texture_fixture.hpp"

using namespace kerf;

namespace {

// Light wood with dark lines across x (the lines run along y) of period `periodPx` and the given
// amplitude, turned by `turnDeg`.
Image lines(int size, double periodPx, double amplitude, double turnDeg) {
  Image image(size, size, 3);
  const double turn = turnDeg * std::numbers::pi / 180.0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = x * std::cos(turn) + y * std::sin(turn);
      const float v = static_cast<float>(0.6 + amplitude * std::sin(2.0 * std::numbers::pi * u / periodPx));
      float* p = image.pixel(x, y);
      p[0] = v, p[1] = 0.8f * v, p[2] = 0.55f * v;
    }
  return image;
}

// Light wood with dark dashes `lengthPx` long along y, 2 px wide, at seeded places (about one per
// 4 x lengthPx px): pores cut along the grain, as long as the species makes them.
Image dashes(int size, int lengthPx, unsigned seed) {
  Image image(size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float* p = image.pixel(x, y);
      p[0] = 0.6f, p[1] = 0.48f, p[2] = 0.33f;
    }
  unsigned state = seed;
  const auto next = [&] { return (state = state * 1664525u + 1013904223u) >> 8; };
  const int count = size * size / (4 * lengthPx);
  for (int i = 0; i < count; ++i) {
    const int x = static_cast<int>(next() % (size - 1)), top = static_cast<int>(next() % size) - lengthPx / 2;
    for (int y = std::max(0, top); y < std::min(size, top + lengthPx); ++y)
      for (int dx = 0; dx < 2; ++dx) {
        float* p = image.pixel(x + dx, y);
        p[0] = 0.3f, p[1] = 0.24f, p[2] = 0.16f;
      }
  }
  return image;
}

}  // namespace

TEST(GrainView, StreakLengthTellsLongPoresFromShortOnes) {
  // At 6.4 px/mm: dashes 64 px (10 mm) long against 13 px (2 mm), the kuri block's truth and a start.
  const GrainView longDashes = grainViewOf(dashes(160, 64, 1)), otherLong = grainViewOf(dashes(160, 64, 2));
  const GrainView shortDashes = grainViewOf(dashes(160, 13, 3));
  // Along the lines the long dashes stay alike for millimetres; the short ones not past 2 mm.
  std::printf("streaks at 1, 2, 4 mm: long %.2f %.2f %.2f, short %.2f %.2f %.2f\n", longDashes.streak[0],
              longDashes.streak[1], longDashes.streak[2], shortDashes.streak[0], shortDashes.streak[1],
              shortDashes.streak[2]);
  EXPECT_GT(longDashes.streak[1], 0.5);
  EXPECT_LT(shortDashes.streak[1], 0.2);
  EXPECT_NEAR(streakDifference(longDashes, longDashes), 0.0, 1e-12);
  // Other dashes of the same length are closer than dashes of another length.
  EXPECT_LT(streakDifference(otherLong, longDashes), 0.1);
  EXPECT_GT(streakDifference(shortDashes, longDashes), 0.3);
  // The lines' direction comes from the image: the same dashes turned by 90 degrees read the same.
  Image turned(160, 160, 3);
  const Image source = dashes(160, 64, 1);
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 160; ++x)
      for (int c = 0; c < 3; ++c) turned.pixel(x, y)[c] = source.pixel(y, x)[c];
  EXPECT_LT(streakDifference(grainViewOf(turned), longDashes), 0.05);
}

TEST(GrainView, SameLinesAgreeAndCrossedLinesDisagree) {
  const GrainView photo = grainViewOf(lines(96, 9.0, 0.2, 20));
  EXPECT_NEAR(grainAgreement(grainViewOf(lines(96, 9.0, 0.2, 20)), photo), 1.0, 1e-6);
  // Other spacing, same direction: the direction is what counts.
  EXPECT_GT(grainAgreement(grainViewOf(lines(96, 6.0, 0.2, 20)), photo), 0.95);
  // Across the grain (cos 2 x 90 deg = -1): the failure of pores running across the fibres.
  EXPECT_LT(grainAgreement(grainViewOf(lines(96, 9.0, 0.2, 110)), photo), -0.95);
  // 45 degrees off: no agreement.
  EXPECT_NEAR(grainAgreement(grainViewOf(lines(96, 9.0, 0.2, 65)), photo), 0.0, 0.05);
}

TEST(GrainView, ContrastIsTheRatioOfTheBandPassedSpread) {
  const GrainView photo = grainViewOf(lines(96, 9.0, 0.2, 0));
  EXPECT_NEAR(contrastRatio(grainViewOf(lines(96, 9.0, 0.1, 0)), photo), 0.5, 0.01);
  EXPECT_NEAR(contrastRatio(grainViewOf(lines(96, 9.0, 0.2, 0)), photo), 1.0, 1e-6);
  // A flat render: no contrast and no direction.
  const GrainView flat = grainViewOf(lines(96, 9.0, 0.0, 0));
  EXPECT_LT(contrastRatio(flat, photo), 1e-3);
  EXPECT_NEAR(grainAgreement(flat, photo), 0.0, 1e-3);
  EXPECT_THROW(grainAgreement(grainViewOf(lines(64, 9.0, 0.2, 0)), photo), InputError);
}

TEST(GrainView, FigureCorrelationSeesWhereTheBandsLie) {
  // Bands 24 px apart (3.75 mm at the photos' 6.4 px/mm): the ring figure's scale.
  const GrainView photo = grainViewOf(lines(96, 24.0, 0.2, 30));
  EXPECT_NEAR(figureCorrelation(grainViewOf(lines(96, 24.0, 0.1, 30)), photo), 1.0, 1e-3);
  // The same bands half a period off: light where the photo is dark.
  Image shifted = lines(128, 24.0, 0.2, 0), reference = lines(128, 24.0, 0.2, 0);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x)
      for (int c = 0; c < 3; ++c) shifted.pixel(x, y)[c] = reference.pixel((x + 12) % 128, y)[c];
  EXPECT_LT(figureCorrelation(grainViewOf(shifted), grainViewOf(reference)), -0.9);
  EXPECT_NEAR(figureCorrelation(grainViewOf(lines(96, 24.0, 0.0, 30)), photo), 0.0, 1e-6);
}

TEST(GrainView, TheObjectiveScoresWashedOutDetailWorse) {
  const test::TextureSynthetic& s = test::textureSynthetic();
  const TextureObjective objective(s.truth.block, s.rates, s.truth.params, s.photos);
  WoodParameters washed = s.sameWoodOtherSeed();
  washed.fiberStrength = 0, washed.poreDensityEarly = 0, washed.poreDensityLate = 0, washed.rayDensity = 0;
  const std::vector<TextureScore> scores = objective.evaluate({s.sameWoodOtherSeed(), washed});
  const TextureScore &truth = scores[0], &flat = scores[1];
  EXPECT_LT(truth.loss, flat.loss);
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    SCOPED_TRACE(std::string(1, faceLetter(face)));
    ASSERT_TRUE(truth.faces[i].used);
    // Other pores and rays than the photo's, the same wood: near the photo's contrast and grain.
    EXPECT_NEAR(truth.faces[i].contrast, 1.0, 0.25);
    EXPECT_GT(truth.faces[i].grain, 0.5);
    EXPECT_GT(truth.faces[i].figure, 0.5);
    // Without pores, rays and fibres only the rings are left. At the grain view's 1 mm scales the dense
    // rings of this block carry most of the contrast (the washed-out faces measured 0.96-1.05 of the
    // truth's), so here the detail shows in the style distance.
    EXPECT_GT(flat.faces[i].style, truth.faces[i].style);
  }
}
