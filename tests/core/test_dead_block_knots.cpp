// Dead knots in the block's growth field (field/block_knots.hpp, issue 19): Larsson et al. 2022
// Sec. 4.2.2 Eq. 5 and Sec. 4.3 on BlockKnot::deathTime, analytically, and dead knots in project JSON.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <numbers>

#include "field/block_knots.hpp"
#include "io/block_knots_json.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

constexpr float kRingWidth = 3.0f;
constexpr float kStemRadius = 60.0f;  // mm from the pith axis at the points below: inside every reach

// The knot time T' (years) of knotTerm at stem time g and distance d from the knot's axis.
float knotTime(float g, float d, float speed, float deathTime, const KnotSettings& s, float beta = 0.0f) {
  return knotTerm(g, d, kStemRadius, speed, kRingWidth, s.knotSmoothStem, s,
                  KnotDeathAt<float>{deathTime, beta})
      .time;
}

// G_k of one knot (Eq. 6 with one term): min(G, T') + smoothing.
float merged(float g, float d, float speed, float deathTime, const KnotSettings& s, float beta = 0.0f) {
  const KnotTerm<float> t = knotTerm(g, d, kStemRadius, speed, kRingWidth, s.knotSmoothStem, s,
                                     KnotDeathAt<float>{deathTime, beta});
  return std::min(g, t.time) + t.smoothing;
}

// The knot's radius at stem time g: where T' = G (bisection on d; T' grows with d).
float knotRadius(float g, float speed, float deathTime, const KnotSettings& s) {
  float lo = 0.0f, hi = 20.0f;
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (knotTime(g, mid, speed, deathTime, s) < g ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}

}  // namespace

// Eq. 5: the branch stops thickening when it dies; its section stays the one it had then.
TEST(DeadBlockKnots, TheKnotStopsThickeningAtItsDeath) {
  const KnotSettings s;
  const float speed = 0.15f, death = 6.0f;
  for (const float g : {2.0f, 4.0f, 6.0f}) {  // alive: the cone of Eq. 7, radius v w G
    EXPECT_NEAR(knotRadius(g, speed, death, s), speed * kRingWidth * g, 1e-4f) << "G " << g;
  }
  const float frozen = speed * kRingWidth * death;
  for (const float g : {6.5f, 8.0f, 12.0f, 20.0f}) {
    EXPECT_NEAR(knotRadius(g, speed, death, s), frozen, 1e-4f) << "G " << g;
    // The same knot alive is thicker by then.
    EXPECT_GT(knotRadius(g, speed, std::numeric_limits<float>::infinity(), s), frozen * g / death - 1e-3f);
  }
}

// A tapering knot (issue 19 item 2) keeps the speed of its death too: a later, slower speed would shrink it.
TEST(DeadBlockKnots, ATaperingKnotKeepsTheSectionOfItsDeath) {
  BlockKnot knot{0, {0, 0, 0}, {1, 0, 0}, 0.15f, 0.5f, 5.0f};
  knot.deathTime = 8.0f;
  KnotSettings s;
  s.knotStemRadius = 150.0f;
  const BlockKnots knots({knot}, s, kRingWidth, {0, 0, 1});
  const float v = knotSpeedAt(knot.speed, knot.taper, knot.taperAge, knot.deathTime, maxKnotSpeed(s));
  const float frozen = v * kRingWidth * knot.deathTime;
  for (const float g : {10.0f, 16.0f}) {
    // Just inside and just outside the frozen section, beside the knot at 30 mm along its axis.
    const BlockKnotSample in = knots.merge({30, 0, frozen - 0.02f}, g, kStemRadius);
    const BlockKnotSample out = knots.merge({30, 0, frozen + 0.02f}, g, kStemRadius);
    EXPECT_LT(in.time, knot.deathTime + 0.05f) << "G " << g;  // the knot's wood, grown before its death
    EXPECT_GT(out.time - in.time, 0.4f * (g - knot.deathTime)) << "G " << g;  // the stem's, around it
  }
}

// Outside the dead knot G_k is continuous, also across the death; at the dead knot's surface it jumps:
// the stem's rings are no longer continuous with the knot (it is encased), while an alive knot's are.
TEST(DeadBlockKnots, TheFieldIsContinuousOutsideTheKnotAndBreaksAtItsEncasedSurface) {
  const KnotSettings s;
  const float speed = 0.15f, death = 6.0f, step = 1e-3f;
  const float frozen = speed * kRingWidth * death;
  for (const float d : {1.5f * frozen, 3.0f * frozen}) {
    float largest = 0.0f;
    for (float g = 2.0f; g < 12.0f; g += step)
      largest =
          std::max(largest, std::abs(merged(g + step, d, speed, death, s) - merged(g, d, speed, death, s)));
    EXPECT_LT(largest, 5.0f * step) << "d " << d;  // no jump: G_k's slope in G stays near 1
  }
  for (const float g : {9.0f, 15.0f}) {
    const float jumpDead =
        merged(g, frozen + 1e-3f, speed, death, s) - merged(g, frozen - 1e-3f, speed, death, s);
    EXPECT_GT(jumpDead, 0.4f * (g - death)) << "G " << g;
    const float alive = std::numeric_limits<float>::infinity();
    const float r = knotRadius(g, speed, alive, s);
    const float jumpAlive = merged(g, r + 1e-3f, speed, alive, s) - merged(g, r - 1e-3f, speed, alive, s);
    EXPECT_LT(std::abs(jumpAlive), 0.01f) << "G " << g;
  }
}

// Sec. 4.2.2: long after the death the fillet is inverted (the rings turn in towards the knot: G_k above
// G), more above and below the knot than beside it (the butterfly); alive, it pushes them out.
TEST(DeadBlockKnots, TheSweepInvertsWithTheButterfly) {
  const KnotSettings s;
  const float speed = 0.15f, death = 6.0f, g = 30.0f;
  const float d = 2.0f * speed * kRingWidth * death;
  const float side = merged(g, d, speed, death, s, 0.0f) - g;
  const float above = merged(g, d, speed, death, s, std::numbers::pi_v<float> / 2) - g;
  EXPECT_GT(side, 0.0f);
  EXPECT_GT(above, 2.0f * side);
  EXPECT_LT(merged(g, d, speed, std::numeric_limits<float>::infinity(), s) - g, 0.0f);
}

// Sec. 4.3 as the log: the dark bark ring where the section froze, and the dead wood darker.
TEST(DeadBlockKnots, ADeadKnotGetsItsBarkRingAndDarkening) {
  BlockKnot knot{0, {0, 0, 0}, {1, 0, 0}, 0.15f};
  KnotSettings s;
  s.knotStemRadius = 150.0f;
  const BlockKnots alive({knot}, s, kRingWidth, {0, 0, 1});
  knot.deathTime = 6.0f;
  const BlockKnots dead({knot}, s, kRingWidth, {0, 0, 1});
  const float frozen = knot.speed * kRingWidth * knot.deathTime, g = 15.0f;
  const glm::vec3 onSurface(30, frozen, 0), inside(30, 0.3f * frozen, 0), beyond(30, 3.0f * frozen, 0);
  EXPECT_EQ(dead.merge(onSurface, g, kStemRadius).shade, s.knotOutlineShade);
  EXPECT_EQ(dead.merge(inside, g, kStemRadius).shade, 1.0f);
  EXPECT_EQ(dead.merge(beyond, g, kStemRadius).shade, 1.0f);
  EXPECT_EQ(alive.merge(onSurface, g, kStemRadius).shade, 1.0f);
  // Inside: the knot's darkness plus the dead shade, min(1, 3 tau) x dead_darkening with tau in stem time.
  const float tau = (g - knot.deathTime) * kRingWidth / s.knotStemRadius;
  EXPECT_NEAR(dead.merge(inside, g, kStemRadius).darkness - alive.merge(inside, g, kStemRadius).darkness,
              std::min(1.0f, 3.0f * tau) * s.knotDeadDarkening, 1e-5f);
  EXPECT_EQ(dead.merge(beyond, g, kStemRadius).darkness, 0.0f);
  // Before the death the knot is as alive.
  EXPECT_EQ(dead.merge(inside, 5.0f, kStemRadius).time, alive.merge(inside, 5.0f, kStemRadius).time);
  EXPECT_EQ(dead.merge(inside, 5.0f, kStemRadius).shade, 1.0f);
}

TEST(DeadBlockKnots, ProjectJsonKeepsTheDeathAndNamesBadEntries) {
  BlockKnot dead{3, {1, 2, -50}, {0, 0, 1}, 0.12f};
  dead.deathTime = 12.75f;
  const std::vector<BlockKnot> knots = {BlockKnot{0, {0, 0, -50}, {0, 1, 1}, 0.1f}, dead};
  const nlohmann::json json = blockKnotsToJson(knots);
  EXPECT_FALSE(json[0].contains("death_years"));  // alive: written as before
  EXPECT_EQ(json[1]["death_years"], 12.75);
  const std::vector<BlockKnot> back = blockKnotsFromJson(nlohmann::json::parse(json.dump()));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_FALSE(back[0].dead());
  EXPECT_EQ(back[1], dead);

  const auto error = [](const std::string& death) {
    try {
      blockKnotsFromJson(nlohmann::json::parse(
          R"([{"id": 0, "origin": [0, 0, 0], "direction": [0, 0, 1], "speed": 0.1, "death_years": )" + death +
          "}]"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("null"), "");  // null: alive
  EXPECT_NE(error("-2").find("knots[0]: the death time must be a positive number"), std::string::npos);
  EXPECT_NE(error("0").find("knots[0]: the death time"), std::string::npos);
  EXPECT_NE(error(R"("soon")").find("knots[0].death_years must be a number"), std::string::npos);
  EXPECT_NE(error("1e60").find("knots[0].death_years"), std::string::npos);
}
