// Block and face geometry: the Mokume face table, pixel <-> 3D round trips, the unfolded cross.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/block.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {
void expectNear(glm::vec3 a, glm::vec3 b, float tol = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}
}  // namespace

TEST(Block, MatchesTheMokumeFaceTable) {
  // MOKUME_CONVENTIONS.md A: pixel (r, c) of a 256 px face sits at u = (c-128)/256, v = (r-128)/256
  // cube units (40 mm); Kerf's continuous coordinate of that point is (c, r), i.e. the pixel corner.
  const Block cube(glm::vec3(40.0f));
  const glm::ivec2 size(256, 256);
  const int c = 37, r = 201;
  const float u = (c - 128) / 256.0f * 40.0f, v = (r - 128) / 256.0f * 40.0f;
  const glm::vec2 pos(c, r);
  expectNear(cube.imageToBlock(FaceId::A, pos, size), {u, -v, 20});
  expectNear(cube.imageToBlock(FaceId::B, pos, size), {u, 20, v});
  expectNear(cube.imageToBlock(FaceId::C, pos, size), {-20, -v, u});
  expectNear(cube.imageToBlock(FaceId::D, pos, size), {u, -20, -v});
  expectNear(cube.imageToBlock(FaceId::E, pos, size), {20, -v, -u});
  expectNear(cube.imageToBlock(FaceId::F, pos, size), {-u, -v, -20});
}

TEST(Block, PixelAndBlockRoundTripOnEveryFace) {
  const Block block(glm::vec3(30.0f, 50.0f, 20.0f));
  for (FaceId face : kAllFaces) {
    const glm::ivec2 size = block.faceImageSize(face, 4.0f);
    const FaceFrame frame = block.face(face);
    EXPECT_EQ(size.x, static_cast<int>(frame.widthMm * 4));
    EXPECT_EQ(size.y, static_cast<int>(frame.heightMm * 4));
    for (glm::vec2 pos :
         {glm::vec2(0.5f, 0.5f), glm::vec2(size.x - 0.5f, 3.25f), glm::vec2(17.0f, size.y - 2.0f)}) {
      const glm::vec3 p = block.imageToBlock(face, pos, size);
      EXPECT_TRUE(block.contains(p)) << faceLetter(face);
      EXPECT_NEAR(glm::dot(p - frame.center, frame.normal), 0.0f, 1e-4f)
          << "point must lie on face " << faceLetter(face);
      const glm::vec2 back = block.blockToImage(face, p, size);
      EXPECT_NEAR(back.x, pos.x, 1e-3f);
      EXPECT_NEAR(back.y, pos.y, 1e-3f);
    }
    // Frames are right-handed and outward: right x down = -normal (we look at the face from outside).
    expectNear(glm::cross(frame.right, frame.down), -frame.normal);
    EXPECT_GT(glm::dot(frame.center, frame.normal), 0.0f);
  }
}

TEST(Block, CrossNeighboursShareTheirEdges) {
  // In the unfolded cross, the pixel row/column on either side of a shared edge maps to the same 3D
  // edge: A's top row meets B's bottom row, A's left column meets C's right column, and so on.
  const Block block(glm::vec3(40.0f, 30.0f, 24.0f));
  const float k = 5.0f;
  struct Edge {
    FaceId a, b;
    bool horizontal;  // true: a's top edge meets b's bottom edge; false: a's right edge meets b's left edge
  };
  const Edge edges[] = {{FaceId::A, FaceId::B, true},
                        {FaceId::D, FaceId::A, true},
                        {FaceId::C, FaceId::A, false},
                        {FaceId::A, FaceId::E, false},
                        {FaceId::E, FaceId::F, false}};
  for (const Edge& e : edges) {
    const glm::ivec2 sa = block.faceImageSize(e.a, k), sb = block.faceImageSize(e.b, k);
    if (e.horizontal) {
      ASSERT_EQ(sa.x, sb.x);
      for (float x : {0.5f, sa.x * 0.5f, sa.x - 0.5f}) {
        expectNear(block.imageToBlock(e.a, {x, 0.0f}, sa), block.imageToBlock(e.b, {x, float(sb.y)}, sb));
      }
    } else {
      ASSERT_EQ(sa.y, sb.y);
      for (float y : {0.5f, sa.y * 0.5f, sa.y - 0.5f}) {
        expectNear(block.imageToBlock(e.a, {float(sa.x), y}, sa), block.imageToBlock(e.b, {0.0f, y}, sb));
      }
    }
  }
}

TEST(Block, FaceLettersAndSlots) {
  for (FaceId face : kAllFaces) EXPECT_EQ(faceFromLetter(faceLetter(face)), face);
  EXPECT_EQ(faceFromLetter('c'), FaceId::C);
  EXPECT_FALSE(faceFromLetter('G').has_value());
  EXPECT_EQ(crossSlot(FaceId::B).row, crossSlot(FaceId::A).row - 1);
  EXPECT_EQ(crossSlot(FaceId::F).column, crossSlot(FaceId::E).column + 1);
}

TEST(Block, RejectsBadSizes) {
  EXPECT_THROW(Block(glm::vec3(0, 1, 1)), InputError);
  EXPECT_THROW(Block(glm::vec3(std::nanf(""), 1, 1)), InputError);
  EXPECT_THROW(Block(glm::vec3(-4, 1, 1)), InputError);
}
