// CLT, rotary-cut veneer and plywood (core/render/layered_panels.hpp, Larsson et al. 2022 Sec. 5): the
// veneer's spiral unrolls to its own length, every CLT lamella's pixels come from its own board, the layers'
// grain alternates, and golden images (random log 3; regenerate with KERF_UPDATE_GOLDEN=1
// build/tests/core/test_core --gtest_filter='Golden*' and look at them).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "field/knot_field.hpp"
#include "render/layered_panels.hpp"
#include "test_files.hpp"

using namespace kerf;

namespace {

const LogModel& randomLog() {
  static const LogModel log = generateRandomLog({3});
  return log;
}

WoodColorMap colors() {
  return woodColorMapFromParameters(WoodParameters{}, randomLog().stem.maxRadius());
}

}  // namespace

TEST(Veneer, SpiralArcLengthEqualsTheUnrolledLength) {
  VeneerPeel peel;
  peel.startRadiusMm = 100.0f;
  peel.thicknessMm = 1.5f;
  peel.axis = {3.0f, -2.0f};
  peel.startHeightMm = 40.0f;
  for (float total : {300.0f, 2000.0f, 15000.0f}) {
    // The knife's path, traced finely: its length is the sheet's length.
    double length = 0.0;
    glm::vec3 previous = peel.toLog(0.0f, 10.0f);
    const int steps = static_cast<int>(total / 0.25f);
    for (int i = 1; i <= steps; ++i) {
      const glm::vec3 p = peel.toLog(total * static_cast<float>(i) / static_cast<float>(steps), 10.0f);
      length += glm::length(glm::dvec3(p - previous));
      previous = p;
    }
    EXPECT_NEAR(length, total, 2e-4 * total) << "sheet of " << total << " mm";
  }
  // One turn of the lathe takes the knife in by one veneer thickness.
  const float oneTurn = std::numbers::pi_v<float> * (100.0f * 100.0f - 98.5f * 98.5f) / 1.5f;
  EXPECT_NEAR(peel.angleAt(oneTurn), 2.0f * std::numbers::pi_v<float>, 1e-4f);
  EXPECT_NEAR(peel.radiusAt(oneTurn), 98.5f, 1e-4f);
  EXPECT_FLOAT_EQ(peel.radiusAt(0.0f), 100.0f);
  // The sheet runs up the log along v, at the knife's radius around the lathe axis.
  const glm::vec3 a = peel.toLog(500.0f, 0.0f), b = peel.toLog(500.0f, 250.0f, 0.5f);
  EXPECT_FLOAT_EQ(a.z, 40.0f);
  EXPECT_FLOAT_EQ(b.z, 290.0f);
  EXPECT_NEAR(glm::length(glm::vec2(a) - peel.axis), peel.radiusAt(500.0f), 1e-3f);
  EXPECT_NEAR(glm::length(glm::vec2(b) - peel.axis), peel.radiusAt(500.0f) - 0.5f, 1e-3f);
}

TEST(Clt, LamellaPixelsComeFromTheirOwnBoard) {
  CltPanel panel = makeCltPanel(randomLog(), {600.0f, 600.0f, 90.0f}, 3, 120.0f, 7);
  ASSERT_EQ(panel.lamellas.size(), 3u);
  ASSERT_EQ(panel.lamellas[2].size(), 5u);
  // Every lamella is its own board: no two share a place in the log.
  std::set<std::tuple<float, float, float>> places;
  for (const auto& layer : panel.lamellas)
    for (const Board& b : layer) places.insert({b.center.x, b.center.y, b.center.z});
  EXPECT_EQ(places.size(), 15u);
  for (auto& layer : panel.shades) std::fill(layer.begin(), layer.end(), 1.0f);  // colours alone
  panel.jointShade = 1.0f;

  const KnotField field(randomLog(), KnotSettings{});
  const WoodColorMap map = colors();
  const int resolution = 120;
  const Image image = renderCltFace(field, map, panel, FaceId::A, resolution);
  const Block block(panel.size);
  const glm::ivec2 size(image.width, image.height);
  int checked = 0;
  for (int y = 3; y < size.y; y += 13) {
    for (int x = 2; x < size.x; x += 7) {
      const glm::vec3 p = block.imageToBlock(FaceId::A, glm::vec2(x + 0.5f, y + 0.5f), size);
      int layer = -1, lamella = -1;
      glm::vec3 q;
      panel.locate(p, layer, lamella, q);
      EXPECT_EQ(layer, 2);  // face A is the top layer
      EXPECT_EQ(lamella, static_cast<int>((p.x + 300.0f) / 120.0f));
      const Board& board = panel.lamellas[layer][lamella];
      EXPECT_LE(std::abs(q.x), 0.5f * board.size.x + 1e-3f);
      EXPECT_LE(std::abs(q.y), 0.5f * board.size.y + 1e-3f);
      EXPECT_NEAR(q.z, 0.5f * board.size.z, 1e-3f);  // the lamella's face A
      const glm::vec3 expected = field.color(field.evaluate(board.toLog(q)), map);
      const float* px = image.pixel(x, y);
      EXPECT_EQ(px[0], expected.x);
      EXPECT_EQ(px[1], expected.y);
      EXPECT_EQ(px[2], expected.z);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(Clt, LayersAlternateTheirGrain) {
  const CltPanel panel = makeCltPanel(randomLog(), {600.0f, 600.0f, 90.0f}, 3, 120.0f, 7);
  // Boards are cut along the log, so a lamella's grain is the log axis (log z).
  const auto grainStep = [&](glm::vec3 p, glm::vec3 step) {
    return panel.map(p + step).logPoint - panel.map(p).logPoint;
  };
  const glm::vec3 top(10.0f, 20.0f, 40.0f), middle(10.0f, 20.0f, 0.0f), bottom(10.0f, 20.0f, -40.0f);
  for (const glm::vec3& p : {top, bottom}) {  // outer layers: grain along the panel's length (y)
    const glm::vec3 d = grainStep(p, {0.0f, 10.0f, 0.0f});
    EXPECT_NEAR(std::abs(d.z), 10.0f, 1e-3f);
    EXPECT_NEAR(glm::length(glm::vec2(d)), 0.0f, 1e-3f);
  }
  const glm::vec3 d = grainStep(middle, {10.0f, 0.0f, 0.0f});  // cross layer: along the width (x)
  EXPECT_NEAR(std::abs(d.z), 10.0f, 1e-3f);
  EXPECT_NEAR(glm::length(glm::vec2(d)), 0.0f, 1e-3f);
}

TEST(Plywood, PliesArePeeledOneAfterAnotherWithAlternatingGrain) {
  const PlywoodPanel panel = makePlywoodPanel(randomLog(), {600.0f, 600.0f, 12.0f}, 5);
  EXPECT_FLOAT_EQ(panel.peel.thicknessMm, 2.4f);
  for (int ply = 1; ply < panel.plies; ++ply)
    EXPECT_GT(panel.plyStartU[ply], panel.plyStartU[ply - 1] + 600.0f);
  // The top ply's grain (log z) runs along the panel's length, the one below it along the width.
  const glm::vec3 top(0.0f, 0.0f, 6.0f), second(0.0f, 0.0f, 2.5f);
  EXPECT_NEAR(panel.map(top + glm::vec3(0, 10, 0)).logPoint.z - panel.map(top).logPoint.z, 10.0f, 1e-3f);
  EXPECT_NEAR(panel.map(second + glm::vec3(10, 0, 0)).logPoint.z - panel.map(second).logPoint.z, 10.0f,
              1e-3f);
  // Across the grain the sheet follows the spiral: 10 mm across is 10 mm of knife path.
  const glm::vec3 a = panel.map(top).logPoint, b = panel.map(top + glm::vec3(10, 0, 0)).logPoint;
  EXPECT_NEAR(glm::length(b - a), 10.0f, 0.01f);
}

namespace {
using kerf::testing::checkGolden;

Image renderGoldenPanel(const std::string& type, FaceId face) {
  const KnotField field(randomLog(), KnotSettings{});
  const WoodColorMap map = colors();
  if (type == "clt") {
    return renderCltFace(field, map, makeCltPanel(randomLog(), {600.0f, 600.0f, 90.0f}, 3, 120.0f, 1), face,
                         320);
  }
  if (type == "plywood")
    return renderPlywoodFace(field, map, makePlywoodPanel(randomLog(), {600.0f, 600.0f, 12.0f}, 5), face,
                             320);
  const float height = knottiestHeight(randomLog(), 600.0f) - 300.0f;
  return renderVeneerSheet(field, map, defaultPeel(randomLog(), 1.5f, height), 0.0f, 1200.0f, 600.0f, 400);
}
}  // namespace

TEST(GoldenPanels, CltFace) {
  checkGolden(renderGoldenPanel("clt", FaceId::A), "panel_clt");
}

TEST(GoldenPanels, CltEdgeShowsCrossLayers) {
  checkGolden(renderGoldenPanel("clt", FaceId::B), "panel_clt_edge");
}

TEST(GoldenPanels, RotaryCutVeneer) {
  checkGolden(renderGoldenPanel("veneer", FaceId::A), "panel_veneer");
}

TEST(GoldenPanels, PlywoodFace) {
  checkGolden(renderGoldenPanel("plywood", FaceId::A), "panel_plywood");
}
