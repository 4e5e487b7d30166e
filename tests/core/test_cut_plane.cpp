// Cutting planes: their 2D frame and their intersection with the block.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/cut_plane.hpp"
#include "util/error.hpp"

using namespace kerf;

TEST(CutPlane, FrameIsOrthonormalAndRightHanded) {
  for (glm::vec3 n : {glm::vec3(1, 2, 3), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0.2f), glm::vec3(-1, 0, 0)}) {
    const CutPlane plane({1, 2, 3}, n);
    EXPECT_NEAR(glm::length(plane.right()), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(plane.up()), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(plane.right(), plane.up()), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(plane.right(), plane.normal()), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::cross(plane.right(), plane.up()), plane.normal()), 1.0f, 1e-5f);
    const glm::vec3 p = plane.toBlock({2.5f, -1.0f});
    const glm::vec2 q = plane.toPlane(p);
    EXPECT_NEAR(q.x, 2.5f, 1e-5f);
    EXPECT_NEAR(q.y, -1.0f, 1e-5f);
  }
}

TEST(CutPlane, PlaneThroughAFaceIsOrientedLikeTheFaceImage) {
  const Block block(glm::vec3(40.0f));
  for (FaceId face : kAllFaces) {
    const FaceFrame f = block.face(face);
    const CutPlane plane(f.center, f.normal);
    EXPECT_NEAR(glm::dot(plane.right(), f.right), 1.0f, 1e-5f) << faceLetter(face);
    EXPECT_NEAR(glm::dot(plane.up(), -f.down), 1.0f, 1e-5f) << faceLetter(face);
  }
}

TEST(CutPlane, BoundsOfAxisAlignedAndDiagonalCuts) {
  const Block block(glm::vec3(40.0f, 30.0f, 20.0f));
  const auto straight = CutPlane({0, 0, 0}, {0, 0, 1}).boundsInBlock(block);
  ASSERT_TRUE(straight);
  EXPECT_NEAR(straight->max.x - straight->min.x, 40.0f, 1e-4f);
  EXPECT_NEAR(straight->max.y - straight->min.y, 30.0f, 1e-4f);
  // A 45 degree cut through the centre of a cube spans the face diagonal one way and a side the other.
  const auto diagonal = CutPlane({0, 0, 0}, {1, 0, 1}).boundsInBlock(Block(glm::vec3(40.0f)));
  ASSERT_TRUE(diagonal);
  EXPECT_NEAR(diagonal->max.x - diagonal->min.x, 40.0f * std::sqrt(2.0f), 1e-3f);
  EXPECT_NEAR(diagonal->max.y - diagonal->min.y, 40.0f, 1e-3f);
  EXPECT_FALSE(CutPlane({0, 0, 50}, {0, 0, 1}).boundsInBlock(block));
}

TEST(CutPlane, RejectsDegenerateInput) {
  EXPECT_THROW(CutPlane({0, 0, 0}, {0, 0, 0}), InputError);
  EXPECT_THROW(CutPlane({std::nanf(""), 0, 0}, {0, 0, 1}), InputError);
}

TEST(CutPlaneSetting, AnglesAndSnapping) {
  EXPECT_NEAR((CutPlaneSetting{0, 0, 0}).normal().x, 1.0f, 1e-6f);
  EXPECT_NEAR((CutPlaneSetting{0, 0, 90}).normal().y, 1.0f, 1e-6f);
  EXPECT_NEAR((CutPlaneSetting{0, 90, 0}).normal().z, -1.0f, 1e-6f);
  const CutPlaneSetting s{3.5f, 37.0f, -22.0f};
  const CutPlaneSetting back = CutPlaneSetting::fromPlane(s.plane());
  EXPECT_NEAR(back.offsetMm, 3.5f, 1e-4f);
  EXPECT_NEAR(back.azimuthDeg, 37.0f, 1e-3f);
  EXPECT_NEAR(back.elevationDeg, -22.0f, 1e-3f);
  const CutPlaneSetting snapped = s.snapped(15.0f);
  EXPECT_FLOAT_EQ(snapped.azimuthDeg, 30.0f);
  EXPECT_FLOAT_EQ(snapped.elevationDeg, -15.0f);
  EXPECT_FLOAT_EQ(snapped.offsetMm, 3.5f);
  EXPECT_FLOAT_EQ(CutPlaneSetting({0, 50, 80}).snapped(90.0f).elevationDeg, 90.0f);
}

TEST(CutPlane, PolygonInBlockIsConvexAndCounterClockwise) {
  const Block block(glm::vec3(40.0f, 30.0f, 20.0f));
  EXPECT_EQ(CutPlane({0, 0, 0}, {0, 0, 1}).polygonInBlock(block).size(), 4u);
  EXPECT_EQ(CutPlane({0, 0, 0}, {1, 1, 1}).polygonInBlock(block).size(), 6u);    // the hexagon
  EXPECT_EQ(CutPlane({19, 14, 9}, {1, 1, 1}).polygonInBlock(block).size(), 3u);  // a corner cut off
  EXPECT_TRUE(CutPlane({0, 0, 30}, {0, 0, 1}).polygonInBlock(block).empty());
  const CutPlane plane({2, -1, 3}, {0.3f, 1.0f, -0.4f});
  const auto polygon = plane.polygonInBlock(block);
  ASSERT_GE(polygon.size(), 3u);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec3 a = polygon[i], b = polygon[(i + 1) % polygon.size()],
                    c = polygon[(i + 2) % polygon.size()];
    EXPECT_TRUE(block.contains(a));
    EXPECT_NEAR(glm::dot(a - plane.point(), plane.normal()), 0.0f, 1e-4f);
    EXPECT_GT(glm::dot(glm::cross(b - a, c - b), plane.normal()), 0.0f);  // turns left seen from +n
  }
}
