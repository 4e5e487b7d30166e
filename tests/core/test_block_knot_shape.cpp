// A block knot in a woodworker's words (field/block_knot_shape.hpp): what the editor's knot table shows
// and edits. An unchanged shape gives back the knot bit for bit; each edit moves only what it names;
// the knot's axis comes out of the demo block on the faces of its marks, as thick as T_k < G says, and a
// dead knot there is as thick as at its death.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "demo/demo_block.hpp"
#include "field/block_knot_shape.hpp"
#include "render/wood_model.hpp"

using namespace kerf;

namespace {

struct DemoKnot {
  Project project = [] {
    Project p = demoProject();
    addDemoKnot(p);
    return p;
  }();
  WoodModel model{project};
  const BlockKnot& knot() const { return model.knots().knots().at(0); }
  const PithAxis& pith() const { return model.field().axis(); }
};

}  // namespace

TEST(BlockKnotShape, UnchangedShapeKeepsTheKnot) {
  const DemoKnot demo;
  BlockKnot off = demo.knot();
  off.origin += glm::vec3(0.7f, -0.2f, 0.3f);  // off the pith: kept
  off.taper = 0.4f;
  off.deathTime = 12.0f;
  EXPECT_EQ(reshapeBlockKnot(off, describeBlockKnot(off, demo.pith()), demo.pith()), off);
}

TEST(BlockKnotShape, DescribesTheDemoKnot) {
  const DemoKnot demo;
  const BlockKnotShape s = describeBlockKnot(demo.knot(), demo.pith());
  // addDemoKnot leans the knot up by a quarter of its run: atan(4) from the pith.
  EXPECT_NEAR(s.angleToPithDeg, std::atan(4.0) * 180.0 / 3.14159265, 0.5);
  EXPECT_NEAR(s.heightMm, glm::dot(demo.knot().origin, demo.pith().direction), 1e-5);
  EXPECT_EQ(s.speed, demo.knot().speed);
  EXPECT_FALSE(std::isfinite(s.deathYears));
}

TEST(BlockKnotShape, EachEditMovesOnlyWhatItNames) {
  const DemoKnot demo;
  const BlockKnot& k = demo.knot();
  const BlockKnotShape s = describeBlockKnot(k, demo.pith());

  BlockKnotShape angle = s;
  angle.angleToPithDeg = 90.0f;
  const BlockKnot turned = reshapeBlockKnot(k, angle, demo.pith());
  EXPECT_NEAR(glm::dot(turned.direction, demo.pith().direction), 0.0f, 1e-5f);
  EXPECT_EQ(turned.origin, k.origin);
  EXPECT_NEAR(describeBlockKnot(turned, demo.pith()).aroundDeg, s.aroundDeg, 1e-3f);

  BlockKnotShape around = s;
  around.aroundDeg = s.aroundDeg + 90.0f;
  const BlockKnot swung = reshapeBlockKnot(k, around, demo.pith());
  EXPECT_NEAR(describeBlockKnot(swung, demo.pith()).angleToPithDeg, s.angleToPithDeg, 1e-3f);
  EXPECT_NEAR(
      glm::dot(swung.direction, glm::normalize(k.direction)),
      std::cos(s.angleToPithDeg * 3.14159265f / 180.0f) * std::cos(s.angleToPithDeg * 3.14159265f / 180.0f),
      1e-4f);

  BlockKnotShape height = s;
  height.heightMm = s.heightMm + 5.0f;
  const BlockKnot raised = reshapeBlockKnot(k, height, demo.pith());
  EXPECT_NEAR(glm::length(raised.origin - k.origin - 5.0f * demo.pith().direction), 0.0f, 1e-4f);
  EXPECT_EQ(raised.direction, k.direction);

  BlockKnotShape dead = s;
  dead.deathYears = 9.0f;
  dead.taper = 0.2f;
  dead.speed = 0.11f;
  const BlockKnot died = reshapeBlockKnot(k, dead, demo.pith());
  EXPECT_EQ(died.deathTime, 9.0f);
  EXPECT_EQ(died.taper, 0.2f);
  EXPECT_EQ(died.speed, 0.11f);
  EXPECT_EQ(died.origin, k.origin);
  EXPECT_EQ(died.direction, k.direction);
}

TEST(BlockKnotShape, ComesOutOnTheFacesOfItsMarks) {
  const DemoKnot demo;
  const std::vector<KnotCrossing> out =
      knotCrossings(demo.knot(), demo.model.block(), demo.model.field(), demo.model.knots().settings());
  ASSERT_EQ(out.size(), 2u);
  ASSERT_EQ(demo.project.annotations.knots.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(out[i].face, demo.project.annotations.knots[i].face);
    // On the face, and on the knot's axis.
    EXPECT_NEAR(knotAxisDistance(&demo.knot().origin.x, &demo.knot().direction.x, out[i].point), 0.0f, 1e-3f);
    const float g = demo.model.field().evaluate(out[i].point);
    EXPECT_NEAR(out[i].stemYears, g, 1e-4f);
    EXPECT_NEAR(out[i].diameterMm, 2.0f * demo.knot().speed * demo.model.field().ringWidth() * g, 1e-3f);
  }
  EXPECT_LT(out[0].stemYears, out[1].stemYears);  // in, then out
  // Dead before it reaches the block: as thick on both faces as at its death.
  BlockKnot dead = demo.knot();
  dead.deathTime = 0.5f * out[0].stemYears;
  for (const KnotCrossing& c :
       knotCrossings(dead, demo.model.block(), demo.model.field(), demo.model.knots().settings()))
    EXPECT_NEAR(c.diameterMm, 2.0f * dead.speed * demo.model.field().ringWidth() * dead.deathTime, 1e-3f);
  // The Dead box's death lies between the two faces.
  const float middle = middleStemYears(demo.knot(), demo.model.block(), demo.model.field());
  EXPECT_GT(middle, out[0].stemYears);
  EXPECT_LT(middle, out[1].stemYears);
}

TEST(BlockKnotShape, AKnotMissingTheBlockHasNoCrossings) {
  const DemoKnot demo;
  BlockKnot away = demo.knot();
  away.origin += 500.0f * demo.pith().direction;  // far up the stem
  EXPECT_TRUE(
      knotCrossings(away, demo.model.block(), demo.model.field(), demo.model.knots().settings()).empty());
  EXPECT_GE(middleStemYears(away, demo.model.block(), demo.model.field()), 1.0f);
}
