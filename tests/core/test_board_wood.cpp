// The wood of a board at any point (core/render/board_wood.hpp): the 3D grid of knot lists that the
// editor's 3D view and cut panel use per fragment changes no sample, bit for bit.
#include <gtest/gtest.h>

#include <random>

#include "render/board_wood.hpp"
#include "spruce_log.hpp"

using namespace kerf;

namespace {

bool sameSample(const KnotFieldSample& a, const KnotFieldSample& b) {
  return a.time == b.time && a.darkness == b.darkness && a.deadShade == b.deadShade &&
         a.outline == b.outline && a.knotsInReach == b.knotsInReach;
}

// Random points of the board, its surface and a hair outside (the cut surface's edges), evaluated over
// their cell's list and over every knot.
void checkGridChangesNothing(const KnotField& field, const Board& board, const std::string& what) {
  const KnotCellGrid grid = buildKnotCellGrid(field, board, knotGridCells(board.size));
  ASSERT_EQ(grid.ranges.size(), static_cast<std::size_t>(grid.cells.x) * grid.cells.y * grid.cells.z) << what;
  EXPECT_LE(grid.meanKnotsPerCell(), static_cast<double>(grid.boardKnots)) << what;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-0.5f, 0.5f);
  int differ = 0, withKnots = 0;
  const int points = 20000;
  for (int i = 0; i < points; ++i) {
    glm::vec3 p(unit(random), unit(random), unit(random));
    if (i % 4 == 0) p[i / 4 % 3] = (i / 12) % 2 ? 0.5f : -0.5f;  // on a face
    p *= board.size;
    if (i % 16 == 1) p += glm::vec3(0.02f, -0.02f, 0.02f);  // just outside
    const glm::ivec3 cell = grid.cellOf(p, board.size);
    const glm::ivec2 range = grid.ranges[grid.cellIndex(cell)];
    const std::span<const int> knots(grid.list.data() + range.x, static_cast<std::size_t>(range.y));
    const glm::vec3 q = board.toLog(p);
    const KnotFieldSample all = field.evaluate(q);
    differ += !sameSample(field.evaluate(q, knots), all);
    withKnots += all.knotsInReach > 0;
  }
  EXPECT_EQ(differ, 0) << what << ": " << differ << " of " << points << " samples changed";
  EXPECT_GT(withKnots, points / 50) << what << ": too few samples near a knot to test anything";
}

}  // namespace

TEST(BoardWood, GridCellsAreAboutCubic) {
  EXPECT_EQ(knotGridCells({110.0f, 110.0f, 30.0f}), glm::ivec3(16, 16, 5));
  EXPECT_EQ(knotGridCells({20.0f, 2000.0f, 20.0f}), glm::ivec3(1, 16, 1));
  EXPECT_EQ(knotGridCells({50.0f, 50.0f, 50.0f}, 8), glm::ivec3(8, 8, 8));
}

TEST(BoardWood, GridChangesNoSample) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const LogModel log = generateRandomLog({.seed = seed, .lengthMm = 1000.0f, .radiusMm = 100.0f});
    const KnotField field(log, KnotSettings{});
    checkGridChangesNothing(field, defaultBoard(log), "default board, seed " + std::to_string(seed));
    Board b;  // slanted and rotated, through the pith
    b.center = glm::vec3(10.0f * seed, -15.0f, 300.0f + 150.0f * seed);
    b.size = glm::vec3(120.0f, 300.0f, 25.0f);
    b.rotationDeg = glm::vec3(17.0f * seed, 40.0f * seed, 8.0f);
    checkGridChangesNothing(field, b, "rotated board, seed " + std::to_string(seed));
  }
}

TEST(BoardWood, GridChangesNoSampleSpruceLog) {
  const LogModel* gran = kerf::testing::granLog();
  if (!gran) GTEST_SKIP() << "the spruce log (shared/data/logs/spruce-gran1) is absent";
  const KnotField field(*gran, KnotSettings{});
  checkGridChangesNothing(field, defaultBoard(*gran), "default board of the spruce log");
  Board b = defaultBoard(*gran);
  b.rotationDeg += glm::vec3(10.0f, 25.0f, -5.0f);
  checkGridChangesNothing(field, b, "rotated board of the spruce log");
}
