// Boards cut from logs (core/render/board_renderer.hpp): knot culling changes no pixel, board placement,
// and golden images of boards from the CT-measured spruce log (regenerate with KERF_UPDATE_GOLDEN=1
// build/tests/core/test_core --gtest_filter='Golden*' and look at them).
#include <gtest/gtest.h>

#include "spruce_log.hpp"
#include "test_files.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "field/knot_field.hpp"
#include "io/log_data_import.hpp"
#include "render/board_renderer.hpp"
#include "util/error.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

const LogModel& gran() {
  return *kerf::testing::granLog();
}

void expectSameImage(const Image& a, const Image& b, const std::string& what) {
  ASSERT_EQ(a.width, b.width) << what;
  ASSERT_EQ(a.height, b.height) << what;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(differ, 0u) << what << ": culling changed " << differ << " channel values";
}

void checkCullingChangesNothing(const KnotField& field, const WoodColorMap& colors, const Board& board,
                                int resolution, const std::string& what) {
  BoardRenderOptions culled, all;
  culled.resolution = all.resolution = resolution;
  all.cull = false;
  BoardRenderStats culledStats, allStats;
  const Image a = renderBoardFace(field, colors, board, culled, &culledStats);
  const Image b = renderBoardFace(field, colors, board, all, &allStats);
  expectSameImage(a, b, what);
  EXPECT_DOUBLE_EQ(culledStats.meanKnotsInReach, allStats.meanKnotsInReach) << what;
  EXPECT_LE(culledStats.meanTileKnots, culledStats.boardKnots) << what;
  EXPECT_EQ(allStats.boardKnots, static_cast<int>(field.log().knots.size())) << what;
}

}  // namespace

TEST(BoardRender, CullingChangesNoPixelRandomLogs) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const LogModel log = generateRandomLog({.seed = seed, .lengthMm = 1000.0f, .radiusMm = 100.0f});
    const KnotField field(log, KnotSettings{});
    const WoodColorMap colors = woodColorMapFromParameters(WoodParameters{}, log.stem.maxRadius());
    checkCullingChangesNothing(field, colors, defaultBoard(log), 96,
                               "default board, seed " + std::to_string(seed));
    // Slanted and rotated boards, some through the pith.
    Board b;
    b.center = glm::vec3(10.0f * seed, -15.0f, 300.0f + 150.0f * seed);
    b.size = glm::vec3(120.0f, 300.0f, 25.0f);
    b.rotationDeg = glm::vec3(17.0f * seed, 40.0f * seed, 8.0f);
    checkCullingChangesNothing(field, colors, b, 96, "rotated board, seed " + std::to_string(seed));
  }
}

TEST(BoardRender, CullingChangesNoPixelSpruceLog) {
  SKIP_WITHOUT_GRAN();
  const KnotField field(gran(), KnotSettings{});
  checkCullingChangesNothing(field, gran().colorMap, defaultBoard(gran()), 160, "default board");
  checkCullingChangesNothing(field, gran().colorMap, boardAlongKnot(gran(), 40, {150.0f, 150.0f, 30.0f}), 160,
                             "along knot 40");
  Board plank;  // a long plank through the pith region
  plank.center = glm::vec3(0.0f, -25.0f, 2000.0f);
  plank.size = glm::vec3(200.0f, 1200.0f, 40.0f);
  plank.rotationDeg = glm::vec3(2.0f, 0.0f, 0.0f);
  checkCullingChangesNothing(field, gran().colorMap, plank, 240, "long plank");
  BoardRenderStats stats;
  BoardRenderOptions options;
  options.resolution = 200;
  renderBoardFace(field, gran().colorMap, defaultBoard(gran()), options, &stats);
  EXPECT_LT(stats.boardKnots, 40) << "per-board culling keeps the knots near the board";
  EXPECT_LT(stats.meanTileKnots, stats.boardKnots) << "per-tile culling keeps fewer";
}

TEST(BoardRender, BoardPlacement) {
  Board b;
  b.center = glm::vec3(1.0f, 2.0f, 3.0f);
  // No rotation: length up the log, face A looking towards -y.
  EXPECT_NEAR(glm::length(b.axes()[1] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(b.axes()[2] - glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(b.toLog({0, 10, 0}) - glm::vec3(1, 2, 13)), 0.0f, 1e-5f);
  // ry turns the board about the log axis.
  b.rotationDeg = glm::vec3(0.0f, 90.0f, 0.0f);
  EXPECT_NEAR(glm::length(b.axes()[2] - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(b.axes()[1] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  // Text form.
  const Board parsed = parseBoard("1,2,3,100,200,30,0,45,5");
  EXPECT_EQ(parsed.size, glm::vec3(100, 200, 30));
  EXPECT_EQ(parsed.rotationDeg, glm::vec3(0, 45, 5));
  EXPECT_EQ(parseBoard("0,0,500,50,60,20").rotationDeg, glm::vec3(0.0f));
  EXPECT_THROW(parseBoard("1,2,3"), InputError);
  EXPECT_THROW(parseBoard("1,2,3,4,5,x"), InputError);
  EXPECT_THROW(parseBoard("0,0,0,10,-1,10"), InputError);
  // A board across a knot: face A lies at the asked distance from the pith and looks at it.
  const LogModel log = generateRandomLog({.seed = 9});
  const Board across = boardAcrossKnot(log, 0, 40.0f, {80.0f, 80.0f, 20.0f});
  const glm::vec3 faceCentre = across.toLog({0.0f, 0.0f, 10.0f});
  const glm::vec2 pith = log.stem.pithAt(faceCentre.z);
  EXPECT_NEAR(glm::length(glm::vec2(faceCentre) - pith), 40.0f, 1e-3f);
  EXPECT_LT(glm::dot(glm::vec2(across.axes()[2]), glm::vec2(faceCentre) - pith), 0.0f);
}

TEST(BoardRender, ResolutionIsTheLongerSide) {
  const LogModel log = generateRandomLog({.seed = 4});
  const KnotField field(log, KnotSettings{});
  Board b = defaultBoard(log);
  b.size = glm::vec3(50.0f, 200.0f, 20.0f);
  BoardRenderOptions options;
  options.resolution = 100;
  const Image img = renderBoardFace(field, woodColorMapFromParameters(WoodParameters{}, 120.0f), b, options);
  EXPECT_EQ(img.width, 25);
  EXPECT_EQ(img.height, 100);
}

namespace {

using kerf::testing::checkGolden;
using kerf::testing::earlyDeadKnot;

Image renderGran(const Board& board, int resolution, const KnotSettings& settings = {}) {
  const KnotField field(gran(), settings);
  BoardRenderOptions options;
  options.resolution = resolution;
  return renderBoardFace(field, gran().colorMap, board, options);
}

}  // namespace

TEST(GoldenKnots, FlatSawnBoardThroughKnots) {
  SKIP_WITHOUT_GRAN();
  checkGolden(renderGran(defaultBoard(gran()), 320), "knots_flat_sawn");
}

TEST(GoldenKnots, BoardAlongKnotAxis) {
  SKIP_WITHOUT_GRAN();
  checkGolden(renderGran(boardAlongKnot(gran(), 40, {130.0f, 130.0f, 30.0f}), 320), "knots_along_axis");
}

TEST(GoldenKnots, DeadKnotWithButterfly) {
  SKIP_WITHOUT_GRAN();
  const int knot = earlyDeadKnot(gran());
  ASSERT_GE(knot, 0);
  const float distance = gran().knots[knot].deathDistance + 25.0f;
  checkGolden(renderGran(boardAcrossKnot(gran(), knot, distance, {80.0f, 80.0f, 20.0f}), 320),
              "knots_dead_butterfly");
}
