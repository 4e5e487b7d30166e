// The wood of a board at any point (core/render/board_wood.hpp): the 3D grid of knot lists that the
// editor's 3D view and cut panel use per fragment changes no sample, bit for bit.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <random>
#include <string>

#include "render/board_renderer.hpp"
#include "render/board_wood.hpp"
#include "spruce_log.hpp"
#include "util/error.hpp"

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

// Issue 21: a board far from the log is refused; one reaching into the stem from outside still renders.
TEST(BoardWood, BoardOutsideTheLogIsRefusedABoardReachingIntoItIsNot) {
  const LogModel log = generateRandomLog({.seed = 3, .lengthMm = 1000.0f, .radiusMm = 100.0f});
  const float r = log.stem.maxRadius();
  Board board;
  board.size = {100.0f, 100.0f, 30.0f};
  const float reach = 0.5f * glm::length(board.size);
  board.center = {r + reach - 5.0f, 0.0f, 500.0f};  // its corner region reaches 5 mm into the stem's bound
  EXPECT_NO_THROW(checkBoardMeetsLog(log, board));
  board.center = {1.0e6f, 0.0f, 500.0f};
  EXPECT_THROW(checkBoardMeetsLog(log, board), InputError);
  board.center = {0.0f, 0.0f, log.stem.height() + reach + 1.0f};  // above the log's top slice
  EXPECT_THROW(checkBoardMeetsLog(log, board), InputError);
  board.center = {0.0f, 0.0f, -reach + 1.0f};  // overlapping the bottom slice
  EXPECT_NO_THROW(checkBoardMeetsLog(log, board));
}

// Issue 21: one wrong stem radius is refused by name; the real CT log's radii all pass (test_log_io).
TEST(BoardWood, ImplausibleStemRadiusIsRefusedNamingIt) {
  LogModel log = generateRandomLog({.seed = 3, .lengthMm = 1000.0f, .radiusMm = 100.0f});
  EXPECT_NO_THROW(validate(log));
  log.stem.radii[static_cast<std::size_t>(2 * log.stem.azimuths + 7)] = 1.0e30f;
  try {
    validate(log);
    FAIL() << "a stem radius of 1e30 mm was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1e+30 mm at slice 2, azimuth 7 is not plausible"),
              std::string::npos)
        << e.what();
  }
}
