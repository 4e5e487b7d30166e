// Contour extraction exactly as the Mokume authors' code (MOKUME_CONVENTIONS.md section C).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/image.hpp"
#include "rings/contours.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

Image blankArl(int size) {
  return Image(size, size, 1);
}

}  // namespace

TEST(Contours, MokumeSampleCN03HasTheAuthorsContourCounts) {
  const fs::path folder = fs::path(KERF_SHARED_DIR) / "data" / "mokume" / "CN03";
  if (!fs::is_directory(folder))
    GTEST_SKIP() << "reference data not found at " << folder << " (../shared absent)";
  const int expected[6] = {10, 19, 20, 20, 24, 8};  // MOKUME_CONVENTIONS.md section C
  for (FaceId face : kAllFaces) {
    const Image arl = readImage(folder / (std::string(1, faceLetter(face)) + "_arl-unet.png"));
    const auto contours = extractContours(arl, face);
    EXPECT_EQ(static_cast<int>(contours.size()), expected[faceIndex(face)]) << faceLetter(face);
    for (const FaceContour& c : contours) {
      EXPECT_EQ(c.face, face);
      EXPECT_GT(c.pixels.size(), 32u);
      for (const glm::ivec2& p : c.pixels) {
        EXPECT_GE(p.x, 0);
        EXPECT_LT(p.x, arl.width);
        EXPECT_GE(p.y, 0);
        EXPECT_LT(p.y, arl.height);
      }
    }
  }
}

TEST(Contours, ABandAcrossTheFaceGivesTwoOpenContours) {
  Image arl = blankArl(256);
  for (int y = 100; y < 104; ++y)
    for (int x = 0; x < 256; ++x) arl.pixel(x, y)[0] = 1.0f;
  const auto contours = extractContours(arl, FaceId::C);
  ASSERT_EQ(contours.size(), 2u);
  for (const FaceContour& c : contours) {
    EXPECT_EQ(c.face, FaceId::C);
    // Each runs along one edge of the band, from border to border.
    int minX = 1000, maxX = -1;
    for (const glm::ivec2& p : c.pixels) {
      EXPECT_TRUE(p.y == 100 || p.y == 103) << p.y;
      minX = std::min(minX, p.x);
      maxX = std::max(maxX, p.x);
    }
    EXPECT_LE(minX, 6);
    EXPECT_GE(maxX, 250);
  }
}

TEST(Contours, ThresholdIsStrictlyAbove200) {
  Image arl = blankArl(256);
  for (int y = 100; y < 104; ++y)
    for (int x = 0; x < 256; ++x) arl.pixel(x, y)[0] = 200.0f / 255.0f;
  EXPECT_TRUE(extractContours(arl, FaceId::A).empty());
  for (int y = 100; y < 104; ++y)
    for (int x = 0; x < 256; ++x) arl.pixel(x, y)[0] = 201.0f / 255.0f;
  EXPECT_EQ(extractContours(arl, FaceId::A).size(), 2u);
}

TEST(Contours, AnInteriorRingIsKeptWholeAndShortPiecesAreDropped) {
  Image arl = blankArl(256);
  // A closed ring in the middle: outer and inner boundary, both kept whole.
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const float r = std::hypot(x - 128.0f, y - 128.0f);
      if (r > 40 && r < 44) arl.pixel(x, y)[0] = 1.0f;
    }
  // A short stub touching the left border: its pieces have too few points.
  for (int y = 20; y < 23; ++y)
    for (int x = 0; x < 10; ++x) arl.pixel(x, y)[0] = 1.0f;
  const auto contours = extractContours(arl, FaceId::B);
  ASSERT_EQ(contours.size(), 2u);
  for (const FaceContour& c : contours) EXPECT_GT(c.pixels.size(), 200u);
}

TEST(Contours, MarginsScaleWithTheImage) {
  // At 512 px the margin is 10 px: a band ending 8 px from the right border is trimmed there.
  Image arl = blankArl(512);
  for (int y = 200; y < 206; ++y)
    for (int x = 0; x < 504; ++x) arl.pixel(x, y)[0] = 1.0f;
  const auto contours = extractContours(arl, FaceId::A);
  EXPECT_EQ(contours.size(), 2u);
  ContourOptions narrow;
  narrow.margin = 5;
  // With the 256 px margin the right end is not near the border: the end cap joins the two edges.
  EXPECT_EQ(extractContours(arl, FaceId::A, narrow).size(), 1u);
}

TEST(Contours, PixelsLiftToTheFaceInBothConventions) {
  const Block block(glm::vec3(40.0f));
  FaceContour contour{FaceId::A, {{0, 0}, {128, 128}, {255, 10}}};
  const auto kerf = contourToBlock(contour, block, {256, 256});
  const auto mokume = contourToBlock(contour, block, {256, 256}, PixelAnchor::MokumeCorner);
  ASSERT_EQ(kerf.size(), 3u);
  // Face A: z = +20, x = u, y = -v; Mokume: u = (c - 128)/256 cube units of 40 mm.
  EXPECT_NEAR(mokume[1].x, 0.0f, 1e-4f);
  EXPECT_NEAR(mokume[1].y, 0.0f, 1e-4f);
  EXPECT_NEAR(mokume[1].z, 20.0f, 1e-4f);
  EXPECT_NEAR(mokume[2].x, (255 - 128) / 256.0f * 40.0f, 1e-4f);
  EXPECT_NEAR(mokume[2].y, -(10 - 128) / 256.0f * 40.0f, 1e-4f);
  EXPECT_NEAR(kerf[0].x, -20.0f + 0.5f * 40.0f / 256.0f, 1e-4f);
  EXPECT_NEAR(kerf[0].y, 20.0f - 0.5f * 40.0f / 256.0f, 1e-4f);
}
