// Rectifying the user's photos of block faces (io/face_photo_rectify.hpp): a synthetic face is
// "photographed" through a known homography, then rectified back from the known corners.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <functional>
#include <glm/geometric.hpp>

#include "io/face_photo_rectify.hpp"
#include "io/image.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

using Pattern = std::function<glm::vec3(glm::vec2)>;  // colour at a continuous face coordinate

// Rings-like content with a coloured marker in the top-left quarter: smooth enough to interpolate,
// but not symmetric under any turn or mirror.
Pattern facePattern(glm::vec2 size) {
  return [size](glm::vec2 p) {
    const float r = glm::length(p - glm::vec2(-0.2f * size.x, 1.3f * size.y));
    const float ring = 0.5f + 0.5f * std::sin(r * 0.45f);
    glm::vec3 c(0.35f + 0.4f * ring, 0.25f + 0.3f * ring, 0.15f + 0.15f * ring);
    if (p.x < 0.25f * size.x && p.y < 0.25f * size.y) c = {0.9f, 0.1f, 0.1f};
    return c;
  };
}

// The 3x3 homography taking src[k] to dst[k].
Eigen::Matrix3d homography(const std::array<glm::vec2, 4>& src, const std::array<glm::vec2, 4>& dst) {
  Eigen::Matrix<double, 8, 8> a;
  Eigen::Matrix<double, 8, 1> b;
  for (int k = 0; k < 4; ++k) {
    const double x = src[k].x, y = src[k].y, u = dst[k].x, v = dst[k].y;
    a.row(2 * k) << x, y, 1, 0, 0, 0, -u * x, -u * y;
    a.row(2 * k + 1) << 0, 0, 0, x, y, 1, -v * x, -v * y;
    b(2 * k) = u, b(2 * k + 1) = v;
  }
  const Eigen::Matrix<double, 8, 1> h = a.fullPivLu().solve(b);
  Eigen::Matrix3d m;
  m << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), 1;
  return m;
}

glm::vec2 apply(const Eigen::Matrix3d& m, glm::vec2 p) {
  const Eigen::Vector3d q = m * Eigen::Vector3d(p.x, p.y, 1);
  return {static_cast<float>(q.x() / q.z()), static_cast<float>(q.y() / q.z())};
}

// Renders `picture` (continuous coordinates over pictureSize) seen through the homography that takes its
// corners to `corners` on a photo of photoSize, on a light grey background; 4x4 supersampled.
Image photograph(const Pattern& picture, glm::vec2 pictureSize, const std::array<glm::vec2, 4>& corners,
                 glm::ivec2 photoSize, glm::vec3 background = glm::vec3(0.8f)) {
  const std::array<glm::vec2, 4> rect = {glm::vec2(0, 0), glm::vec2(pictureSize.x, 0), pictureSize,
                                         glm::vec2(0, pictureSize.y)};
  const Eigen::Matrix3d toPicture = homography(corners, rect);
  Image photo(photoSize.x, photoSize.y, 3);
  for (int y = 0; y < photoSize.y; ++y)
    for (int x = 0; x < photoSize.x; ++x) {
      glm::vec3 sum(0.0f);
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx) {
          const glm::vec2 q = apply(toPicture, glm::vec2(x + (sx + 0.5f) / 4, y + (sy + 0.5f) / 4));
          const bool inside = q.x >= 0 && q.y >= 0 && q.x < pictureSize.x && q.y < pictureSize.y;
          sum += inside ? picture(q) : background;
        }
      const glm::vec3 c = sum / 16.0f;
      std::copy_n(&c.x, 3, photo.pixel(x, y));
    }
  return photo;
}

// The pattern sampled as a face image (pixel areas averaged, 4x4).
Image sample(const Pattern& pattern, glm::ivec2 size) {
  Image image(size.x, size.y, 3);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      glm::vec3 sum(0.0f);
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx) sum += pattern(glm::vec2(x + (sx + 0.5f) / 4, y + (sy + 0.5f) / 4));
      const glm::vec3 c = sum / 16.0f;
      std::copy_n(&c.x, 3, image.pixel(x, y));
    }
  return image;
}

// Mean absolute difference inside the image, leaving out a 2 px frame (the face's edge blends with the
// background on the photo).
double innerDifference(const Image& a, const Image& b) {
  double sum = 0;
  int count = 0;
  for (int y = 2; y < a.height - 2; ++y)
    for (int x = 2; x < a.width - 2; ++x)
      for (int c = 0; c < 3; ++c, ++count) sum += std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]);
  return sum / count;
}

const std::array<glm::vec2, 4> kCorners = {glm::vec2(112.3f, 61.7f), glm::vec2(520.8f, 95.2f),
                                           glm::vec2(488.1f, 402.6f), glm::vec2(87.5f, 355.9f)};

FacePhotoSetup setupWith(const std::array<glm::vec2, 4>& corners, int rotation = 0, bool flip = false) {
  FacePhotoSetup setup;
  setup.corners = corners;
  setup.rotationDegrees = rotation;
  setup.flip = flip;
  return setup;
}

}  // namespace

TEST(FacePhotoRectify, RestoresAFaceSeenInPerspective) {
  const glm::ivec2 faceSize(180, 120);  // a cuboid's face: 60 x 40 mm at 3 px/mm
  const Pattern face = facePattern(glm::vec2(faceSize));
  const Image photo = photograph(face, glm::vec2(faceSize), kCorners, {600, 450});
  const Image rectified = rectifyFace(photo, setupWith(kCorners), faceSize);
  ASSERT_EQ(rectified.width, faceSize.x);
  ASSERT_EQ(rectified.height, faceSize.y);
  const Image expected = sample(face, faceSize);
  // About 0.001 when right; corners off by half a photo pixel (a mix-up of the pixel-centre conventions)
  // give 0.0038.
  EXPECT_LT(innerDifference(rectified, expected), 0.0025);
  // Half a pixel off in the corners would shift the rings visibly: check the red marker's edge sits at
  // x = 45 (a quarter of the width) to within a pixel, on the rectified image's row 10.
  EXPECT_GT(rectified.pixel(43, 10)[0], 0.8f);
  EXPECT_LT(rectified.pixel(47, 10)[0] - rectified.pixel(47, 10)[1], 0.3f);
  // The same corners shifted by 6 px must give a clearly different picture (the test can fail).
  std::array<glm::vec2, 4> shifted = kCorners;
  for (glm::vec2& p : shifted) p += glm::vec2(6.0f, 0.0f);
  EXPECT_GT(innerDifference(rectifyFace(photo, setupWith(shifted), faceSize), expected), 0.03);
}

TEST(FacePhotoRectify, AveragesDownBigPhotosWithoutAliasing) {
  // A phone photo: about 5 photo pixels per face pixel, so the area-averaging path runs.
  const glm::ivec2 faceSize(64, 48);
  const Pattern face = facePattern(glm::vec2(faceSize));
  std::array<glm::vec2, 4> corners = kCorners;
  for (glm::vec2& p : corners) p *= 0.75f;
  const Image photo = photograph(face, glm::vec2(faceSize), corners, {450, 340});
  EXPECT_GT(photoResolution(corners, glm::vec2(faceSize), 0).x, 4.0f);
  const Image rectified = rectifyFace(photo, setupWith(corners), faceSize);
  EXPECT_LT(innerDifference(rectified, sample(face, faceSize)), 0.0025);  // 0.0012; corners 1 px off: 0.0033
}

TEST(FacePhotoRectify, TurnsAndMirrorsIntoTheFaceOrientation) {
  // For every quarter turn and flip: the photo shows the face turned back by the inverse, and the
  // rectification with that turn and flip restores the face, at the face's (non-square) size.
  const glm::ivec2 faceSize(150, 96);
  const Pattern face = facePattern(glm::vec2(faceSize));
  const Image expected = sample(face, faceSize);
  for (int rotation : {0, 90, 180, 270})
    for (bool flip : {false, true}) {
      const bool quarter = rotation % 180 != 0;
      const glm::ivec2 pre = quarter ? glm::ivec2(faceSize.y, faceSize.x) : faceSize;
      const Pattern picture = [&](glm::vec2 p) { return face(orientPoint(p, pre, rotation, flip)); };
      const Image photo = photograph(picture, glm::vec2(pre), kCorners, {600, 450});
      const Image rectified = rectifyFace(photo, setupWith(kCorners, rotation, flip), faceSize);
      ASSERT_EQ(rectified.width, faceSize.x) << rotation << flip;
      ASSERT_EQ(rectified.height, faceSize.y) << rotation << flip;
      EXPECT_LT(innerDifference(rectified, expected), 0.002) << "rotation " << rotation << " flip " << flip;
    }
}

TEST(FacePhotoRectify, OrientImageMovesPixelsExactly) {
  // 3 x 2:  0 1 2
  //         3 4 5
  Image image(3, 2, 1);
  for (int i = 0; i < 6; ++i) image.pixels[i] = static_cast<float>(i);
  const auto values = [](const Image& im) { return im.pixels; };
  EXPECT_EQ(values(orientImage(image, 0, false)), (std::vector<float>{0, 1, 2, 3, 4, 5}));
  // A quarter turn clockwise: the left column, read upwards, becomes the top row.
  const Image r90 = orientImage(image, 90, false);
  EXPECT_EQ(r90.width, 2);
  EXPECT_EQ(r90.height, 3);
  EXPECT_EQ(values(r90), (std::vector<float>{3, 0, 4, 1, 5, 2}));
  EXPECT_EQ(values(orientImage(image, 180, false)), (std::vector<float>{5, 4, 3, 2, 1, 0}));
  EXPECT_EQ(values(orientImage(image, 270, false)), (std::vector<float>{2, 5, 1, 4, 0, 3}));
  EXPECT_EQ(values(orientImage(image, 0, true)), (std::vector<float>{2, 1, 0, 5, 4, 3}));
  EXPECT_EQ(values(orientImage(image, 90, true)), (std::vector<float>{0, 3, 1, 4, 2, 5}));
  EXPECT_EQ(values(orientImage(image, -90, false)), values(orientImage(image, 270, false)));
  EXPECT_THROW(orientImage(image, 45, false), InputError);
  // orientPoint agrees with the pixels: the corner (0, 0) of a 3 x 2 picture turned 90 degrees.
  EXPECT_EQ(orientPoint({0, 0}, {3, 2}, 90, false), glm::vec2(2, 0));
  // Sides: a quarter turn clockwise takes the top side to the right; the flip swaps right and left.
  EXPECT_EQ(orientedSide(0, 90, false), 1);
  EXPECT_EQ(orientedSide(0, 90, true), 3);
  EXPECT_EQ(orientedSide(2, 180, true), 0);
}

TEST(FacePhotoRectify, FaceEdgeNeighboursFollowTheCross) {
  EXPECT_EQ(faceEdgeNeighbours(FaceId::A),
            (std::array<FaceId, 4>{FaceId::B, FaceId::E, FaceId::D, FaceId::C}));
  // Every edge is shared: the neighbour across it has `face` across one of its own edges.
  for (FaceId face : kAllFaces)
    for (FaceId other : faceEdgeNeighbours(face)) {
      const auto back = faceEdgeNeighbours(other);
      EXPECT_NE(std::find(back.begin(), back.end(), face), back.end())
          << faceLetter(face) << faceLetter(other);
      EXPECT_NE(other, face);
    }
}

TEST(FacePhotoRectify, RefusesBadCorners) {
  const glm::ivec2 photo(600, 450);
  const auto message = [&](std::array<glm::vec2, 4> corners) -> std::string {
    try {
      validateCorners(corners, photo);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message(kCorners), "");
  // Crossed (corners 3 and 4 swapped: a bow tie).
  EXPECT_NE(message({kCorners[0], kCorners[1], kCorners[3], kCorners[2]}).find("convex"), std::string::npos);
  // Anticlockwise.
  EXPECT_NE(message({kCorners[3], kCorners[2], kCorners[1], kCorners[0]}).find("anticlockwise"),
            std::string::npos);
  // A dent (corner 3 pulled inside).
  EXPECT_NE(
      message({kCorners[0], kCorners[1], glm::vec2(250, 150), kCorners[3]}).find("dents in at corner 3"),
      std::string::npos);
  // Three on a line.
  EXPECT_NE(message({glm::vec2(10, 10), glm::vec2(100, 10), glm::vec2(200, 10), glm::vec2(50, 200)})
                .find("lie on one line"),
            std::string::npos);
  // Two the same.
  EXPECT_NE(message({kCorners[0], kCorners[0], kCorners[2], kCorners[3]}).find("apart"), std::string::npos);
  // Outside the photo, and not a number.
  EXPECT_NE(message({kCorners[0], glm::vec2(700, 95), kCorners[2], kCorners[3]}).find("corner 2"),
            std::string::npos);
  EXPECT_NE(message({kCorners[0], kCorners[1], glm::vec2(NAN, 1), kCorners[3]}).find("not a number"),
            std::string::npos);
  // Tiny.
  EXPECT_NE(
      message({glm::vec2(10, 10), glm::vec2(16, 10), glm::vec2(16, 16), glm::vec2(10, 16)}).find("px^2"),
      std::string::npos);
  // rectifyFace checks too, and refuses a bad size or turn.
  const Image image(600, 450, 3);
  EXPECT_THROW(rectifyFace(image, setupWith({kCorners[3], kCorners[2], kCorners[1], kCorners[0]}), {10, 10}),
               InputError);
  EXPECT_THROW(rectifyFace(image, setupWith(kCorners), {0, 10}), InputError);
  EXPECT_THROW(rectifyFace(image, setupWith(kCorners, 45), {10, 10}), InputError);
}

TEST(FacePhotoRectify, WhiteBalanceRestoresAColourCast) {
  // A warm wood face on light grey paper, photographed under a warm light (red up, blue down).
  const glm::ivec2 faceSize(120, 90);
  const Pattern face = facePattern(glm::vec2(faceSize));
  const Image truth = photograph(face, glm::vec2(faceSize), kCorners, {600, 450}, glm::vec3(0.78f));
  const glm::vec3 cast(1.18f, 1.0f, 0.72f);
  Image photo = truth;
  for (std::size_t i = 0; i < photo.pixels.size(); ++i) photo.pixels[i] *= cast[i % 3];

  for (const bool automatic : {true, false}) {
    const glm::vec3 gains =
        automatic ? autoWhiteBalance(photo) : whiteBalanceFromPatch(photo, {10.0f, 400.0f, 60.0f, 40.0f});
    // The gains undo the cast up to one brightness factor (the paper keeps its luminance).
    const glm::vec3 product = gains * cast;
    EXPECT_NEAR(product.x / product.y, 1.0f, 0.01f) << automatic;
    EXPECT_NEAR(product.z / product.y, 1.0f, 0.01f) << automatic;
    Image balanced = photo;
    applyWhiteBalance(balanced, gains);
    const float* paper = balanced.pixel(20, 420);
    EXPECT_NEAR(paper[0], paper[1], 0.01f);
    EXPECT_NEAR(paper[2], paper[1], 0.01f);
    // The wood stays wood-coloured (not bleached to grey): close to its true colour.
    const float* wood = balanced.pixel(300, 250);
    const float* real = truth.pixel(300, 250);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(wood[c], real[c], 0.03f) << automatic << c;
    EXPECT_GT(wood[0] - wood[2], 0.1f);
  }
  // The gains go into the rectified face through the setup.
  FacePhotoSetup setup = setupWith(kCorners);
  setup.whiteBalance = autoWhiteBalance(photo);
  const Image rectified = rectifyFace(photo, setup, faceSize);
  EXPECT_LT(innerDifference(rectified, sample(face, faceSize)), 0.03);
  // Bad patches.
  EXPECT_THROW(whiteBalanceFromPatch(photo, {700, 10, 10, 10}), InputError);
  EXPECT_THROW(whiteBalanceFromPatch(photo, {10, 10, 0, 10}), InputError);
  Image dark(20, 20, 3);
  EXPECT_THROW(whiteBalanceFromPatch(dark, {0, 0, 20, 20}), InputError);
  EXPECT_EQ(autoWhiteBalance(dark), glm::vec3(1.0f));
}

TEST(FacePhotoRectify, DownscaleKeepsCoordinatesProportional) {
  Image photo(400, 300, 3);
  for (int y = 0; y < 300; ++y)
    for (int x = 0; x < 400; ++x) photo.pixel(x, y)[0] = x < 200 ? 1.0f : 0.0f;
  const Image small = downscaleImage(photo, 100);
  EXPECT_EQ(small.width, 100);
  EXPECT_EQ(small.height, 75);
  EXPECT_NEAR(small.pixel(49, 30)[0], 1.0f, 1e-5f);
  EXPECT_NEAR(small.pixel(50, 30)[0], 0.0f, 1e-5f);
  EXPECT_EQ(downscaleImage(photo, 500).width, 400);
}

TEST(FacePhotoRectify, FaceFromFileName) {
  EXPECT_EQ(faceFromFileName("A_col.png"), FaceId::A);
  EXPECT_EQ(faceFromFileName("b-top.jpg"), FaceId::B);
  EXPECT_EQ(faceFromFileName("F.tif"), FaceId::F);
  EXPECT_EQ(faceFromFileName("e face.png"), FaceId::E);
  EXPECT_EQ(faceFromFileName("Apple.png"), std::nullopt);
  EXPECT_EQ(faceFromFileName("G_col.png"), std::nullopt);
  EXPECT_EQ(faceFromFileName("IMG_1234.jpg"), std::nullopt);
}

TEST(FacePhotoRectify, UnreadablePhotoIsAnInputError) {
  FacePhotoSetup setup = setupWith(kCorners);
  setup.source = std::filesystem::path(KERF_TEST_ARTIFACTS) / "no-such-photo.jpg";
  try {
    rectifyFacePhoto(setup, {10, 10});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-photo.jpg"), std::string::npos);
  }
}
