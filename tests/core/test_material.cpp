// The procedural wood texture: analytic colours, Beer's law, pores, rays, fibre directions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "render/wood_model.hpp"

using namespace kerf;

namespace {

// A model with every random detail switched off: plain rings around a straight pith along y.
WoodParameters plainParameters() {
  WoodParameters p;
  p.pithOrigin = {0, 0, -50};
  p.pithTilt = 0;
  p.ringWidth = 2.0f;
  p.ringColorVariation = 0, p.mottleStrength = 0, p.fiberStrength = 0;
  p.poreDensityEarly = 0, p.poreDensityLate = 0, p.rayDensity = 0, p.distortionAmplitude = 0;
  p.transition = 0;
  p.latewoodFraction = 0.3f;
  p.sapwoodStart = 1000;
  return p;
}

GrowthRates uniformRates(const WoodParameters& p, const Block& block) {
  return GrowthRates::uniform(block, PithAxis::fromAngles(p.pithOrigin, p.pithTilt, p.pithAzimuth));
}

// A point on the block's z axis at growth time `year` for the plain model (pith at z = -50).
glm::vec3 pointAtYear(float year) {
  return {0, 0, -50 + 2.0f * year};
}

void expectColor(glm::vec3 a, glm::vec3 b, float tol = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace

TEST(Material, PlainRingsAreEarlywoodThenLatewood) {
  const Block block(glm::vec3(40.0f));
  const WoodParameters p = plainParameters();
  const WoodModel model(block, p, uniformRates(p, block));
  const WoodSample early = model.evaluate(pointAtYear(25.2f));
  EXPECT_NEAR(early.year, 25.2f, 1e-3f);
  EXPECT_NEAR(early.latewood, 0.0f, 1e-6f);
  expectColor(early.color, p.earlywoodColor);
  const WoodSample late = model.evaluate(pointAtYear(25.85f));
  EXPECT_NEAR(late.latewood, 1.0f, 1e-6f);
  expectColor(late.color, p.latewoodColor);
}

TEST(Material, ColoursInBetweenFollowBeersLaw) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.transition = 1.0f;  // latewood ramps in over the whole earlywood
  const WoodModel model(block, p, uniformRates(p, block));
  const WoodSample mid = model.evaluate(pointAtYear(20.4f));
  ASSERT_GT(mid.latewood, 0.05f);
  ASSERT_LT(mid.latewood, 0.95f);
  const glm::vec3 expected =
      p.earlywoodColor * glm::pow(p.latewoodColor / p.earlywoodColor, glm::vec3(mid.latewood));
  expectColor(mid.color, expected);
}

TEST(Material, SapwoodOutsideTheHeartwoodRadius) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.sapwoodStart = 20, p.sapwoodTransition = 1;
  const WoodModel model(block, p, uniformRates(p, block));
  expectColor(model.evaluate(pointAtYear(15.1f)).color, p.earlywoodColor);
  expectColor(model.evaluate(pointAtYear(25.1f)).color, p.sapwoodEarlywoodColor);
}

TEST(Material, FaceTintMultipliesOnlyItsFace) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.faceTintC = {0.5f, 1.0f, 1.0f};
  const WoodModel model(block, p, uniformRates(p, block));
  const glm::vec3 q = pointAtYear(25.2f);
  EXPECT_NEAR(model.evaluate(q, faceIndex(FaceId::C)).color.x, 0.5f * p.earlywoodColor.x, 1e-5f);
  EXPECT_NEAR(model.evaluate(q, faceIndex(FaceId::D)).color.x, p.earlywoodColor.x, 1e-5f);
  EXPECT_NEAR(model.evaluate(q).color.x, p.earlywoodColor.x, 1e-5f);
}

TEST(Material, RingPorousPoresCrowdTheEarlywood) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.poreDensityEarly = 0.9f, p.poreDensityLate = 0.1f, p.poreRadiusEarly = 0.15f, p.poreRadiusLate = 0.04f;
  const WoodModel model(block, p, uniformRates(p, block));
  // Scan an end-grain cross-section (plane y = 0) and compare pore cover in early- and latewood.
  double earlyCover = 0, lateCover = 0;
  int earlyCount = 0, lateCount = 0;
  for (float x = -15; x < 15; x += 0.05f)
    for (float z = -15; z < 15; z += 0.05f) {
      const WoodSample s = model.evaluate({x, 0, z});
      ASSERT_GE(s.pore, 0.0f);
      ASSERT_LE(s.pore, 1.0f);
      if (s.latewood < 0.01f) earlyCover += s.pore, ++earlyCount;
      if (s.latewood > 0.99f) lateCover += s.pore, ++lateCount;
    }
  ASSERT_GT(earlyCount, 1000);
  ASSERT_GT(lateCount, 1000);
  EXPECT_GT(earlyCover / earlyCount, 5 * lateCover / lateCount);
  EXPECT_GT(earlyCover / earlyCount, 0.01);
}

// Mean pore cover of two models of the same colour over an end-grain cross-section (plane y = 0), in three
// parts of the year (by a's ring phase: part i is [from[i], to[i])); checks the colours are the same.
struct PoreCoverByPart {
  std::array<double, 3> a{}, b{};
};
PoreCoverByPart poreCoverByPart(const WoodModel& a, const WoodModel& b, const std::array<float, 3>& from,
                                const std::array<float, 3>& to) {
  PoreCoverByPart cover;
  std::array<int, 3> count{};
  for (float x = -15; x < 15; x += 0.05f)
    for (float z = -15; z < 15; z += 0.05f) {
      const WoodSample sa = a.evaluate({x, 0, z}), sb = b.evaluate({x, 0, z});
      expectColor(sa.color / glm::max(sa.shade, glm::vec3(1e-6f)),
                  sb.color / glm::max(sb.shade, glm::vec3(1e-6f)), 1e-3f);
      const float phase = a.material().yearPhase(sa.year);
      for (int i = 0; i < 3; ++i)
        if (phase >= from[i] && phase < to[i]) cover.a[i] += sa.pore, cover.b[i] += sb.pore, ++count[i];
    }
  for (int i = 0; i < 3; ++i) {
    EXPECT_GT(count[i], 1000) << i;
    cover.a[i] /= std::max(count[i], 1), cover.b[i] /= std::max(count[i], 1);
  }
  return cover;
}

// pores.earlywood_zone widens the band of earlywood pores without touching the colour: with the earlywood
// 0.4 of the year (latewood share 0.6) and a zone of 2, the ring's first 0.8 is as porous as its earlywood
// and the colour is the same as with a zone of 1.
TEST(Material, TheEarlywoodPoreZoneReachesIntoTheLatewood) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.latewoodFraction = 0.6f;
  p.poreDensityEarly = 0.9f, p.poreDensityLate = 0.1f, p.poreRadiusEarly = 0.15f, p.poreRadiusLate = 0.04f;
  const WoodModel narrow(block, p, uniformRates(p, block));
  p.poreZone = 2.0f;
  const WoodModel wide(block, p, uniformRates(p, block));
  const PoreCoverByPart cover = poreCoverByPart(narrow, wide, {0.0f, 0.45f, 0.85f}, {0.35f, 0.75f, 1.0f});
  EXPECT_NEAR(cover.b[0], cover.a[0], 0.2 * cover.a[0]);
  EXPECT_GT(cover.b[1], 5 * cover.a[1]);      // earlywood pores in the latewood
  EXPECT_NEAR(cover.b[2], cover.a[2], 1e-6);  // the latewood beyond the zone
}

// pores.earlywood_thinning: the zone's first rows stay as dense as without it, its last ones thin out, the
// latewood beyond the zone and the colour do not change. Earlywood 0.4 of the year, zone 2: the pores' zone
// is the first 0.8 of the year, and a thinning of 1 leaves none at its end.
TEST(Material, ThinningKeepsTheEarlywoodPoresDenseAtTheRingLine) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.latewoodFraction = 0.6f, p.poreZone = 2.0f;
  p.poreDensityEarly = 0.9f, p.poreDensityLate = 0.1f, p.poreRadiusEarly = 0.15f, p.poreRadiusLate = 0.04f;
  const WoodModel even(block, p, uniformRates(p, block));
  p.poreEarlyThinning = 1.0f;
  const WoodModel thinned(block, p, uniformRates(p, block));
  const PoreCoverByPart cover = poreCoverByPart(even, thinned, {0.0f, 0.55f, 0.85f}, {0.15f, 0.75f, 1.0f});
  EXPECT_GT(cover.b[0], 0.7 * cover.a[0]);    // the first rows: still dense
  EXPECT_LT(cover.b[1], 0.4 * cover.a[1]);    // the zone's end: thinned out
  EXPECT_NEAR(cover.b[2], cover.a[2], 1e-6);  // the latewood beyond the zone
}

TEST(Material, PoresAreDotsOnEndGrainAndGroovesAlongIt) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.poreDensityEarly = 1.0f, p.poreDensityLate = 1.0f, p.poreRadiusEarly = 0.1f, p.poreRadiusLate = 0.1f;
  p.poreLength = 4.0f;
  const WoodModel model(block, p, uniformRates(p, block));
  // Find a pore centre on the end grain, then walk along the grain (y) and across it (x).
  glm::vec3 centre(0.0f);
  float best = 0;
  for (float x = 0; x < 2; x += 0.01f)
    for (float z = 0; z < 2; z += 0.01f)
      if (const float w = model.evaluate({x, 0, z}).pore; w > best) best = w, centre = {x, 0, z};
  ASSERT_GT(best, 0.8f);
  int along = 0, across = 0;
  for (int i = 1; i <= 10; ++i) {
    along += model.evaluate(centre + glm::vec3(0, 0.1f * i, 0)).pore > 0.05f;
    across += model.evaluate(centre + glm::vec3(0.1f * i, 0, 0)).pore > 0.05f;
  }
  EXPECT_GT(along, across + 3);
}

// Vessels, rays and fibres lie in the growth layers (kernels/wood.glsl inGrowthLayers): two points of one
// ring at different heights, where the rates tilt the ring, share their cross-section position, so a vessel
// through one runs through the other; with uniform rates the frame's radius is the geometric one.
TEST(Material, PoresRunInTheGrowthLayers) {
  const Block block(glm::vec3(40.0f));
  const WoodParameters p = plainParameters();
  const WoodModel concentric(block, p, uniformRates(p, block));
  const glm::vec3 q{3, 5, 10};
  EXPECT_NEAR(concentric.material().locate(q).c.radius, glm::length(glm::vec2(q.x, q.z + 50)), 1e-3f);

  GrowthRates rates = uniformRates(p, block);
  for (int ih = 0; ih < rates.heights; ++ih)
    for (int ia = 0; ia < rates.azimuths; ++ia)
      for (int ir = 0; ir < rates.radii; ++ir)
        rates.at(ih, ia, ir) = 1.0f + 0.5f * static_cast<float>(ih) / static_cast<float>(rates.heights - 1);
  const WoodModel tilted(block, p, rates);
  const WoodMaterial& m = tilted.material();
  const glm::vec3 low{0, -15, 10};
  const float year = m.year(low);
  // The point of the same ring 30 mm higher, on the same ray from the pith (bisection along z).
  float z0 = -45, z1 = 30;
  for (int i = 0; i < 60; ++i) {
    const float z = 0.5f * (z0 + z1);
    (m.year({0, 15, z}) < year ? z0 : z1) = z;
  }
  const glm::vec3 high{0, 15, 0.5f * (z0 + z1)};
  ASSERT_NEAR(m.year(high), year, 1e-3f);
  EXPECT_GT(std::abs(high.z - low.z), 1.0f);  // the ring is tilted: other geometric radii
  const WoodLocation a = m.locate(low), b = m.locate(high);
  EXPECT_NEAR(a.c.x, b.c.x, 1e-2f);
  EXPECT_NEAR(a.c.y, b.c.y, 1e-2f);
  EXPECT_NEAR(a.c.radius, year * p.ringWidth, 1e-2f);
}

TEST(Material, RaysRunRadially) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  p.rayDensity = 1.0f, p.rayOpacity = 1.0f, p.rayWidth = 0.1f, p.rayHeight = 1.0f, p.rayLength = 20.0f;
  p.pithOrigin = {0, 0, 0};
  const WoodModel model(block, p, uniformRates(p, block));
  // On the end grain (y = 0) around the pith, find a ray at radius 5 mm and follow it outwards.
  float bestAngle = 0, best = 0;
  for (float a = 0; a < 6.283f; a += 0.002f)
    if (const float w = model.evaluate({5 * std::cos(a), 0, 5 * std::sin(a)}).ray; w > best)
      best = w, bestAngle = a;
  ASSERT_GT(best, 0.5f);
  const glm::vec3 radial(std::cos(bestAngle), 0, std::sin(bestAngle));
  EXPECT_GT(model.evaluate(radial * 7.0f).ray, 0.3f);  // same band (0..20 mm): the ray goes on outward
  const glm::vec3 tangential(-radial.z, 0, radial.x);
  EXPECT_LT(model.evaluate(radial * 5.0f + tangential * 0.3f).ray, 0.05f);  // thin across
}

TEST(Material, FibreDirectionFollowsTheDistortion) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = plainParameters();
  const WoodModel straight(block, p, uniformRates(p, block));
  const glm::vec3 f = straight.evaluate({3, 4, 5}, -1, true).fiberDirection;
  EXPECT_NEAR(f.y, 1.0f, 1e-5f);  // no distortion: fibres run along the pith

  p.distortionAmplitude = 2.0f, p.distortionScale = 5.0f;
  const WoodModel wavy(block, p, uniformRates(p, block));
  float largest = 0;
  for (float x = -18; x < 18; x += 3)
    for (float y = -18; y < 18; y += 3) {
      const glm::vec3 d = wavy.evaluate({x, y, 4}, -1, true).fiberDirection;
      EXPECT_NEAR(glm::length(d), 1.0f, 1e-4f);
      EXPECT_GT(d.y, 0.3f);  // Liu Eq. 3 keeps J invertible: fibres never flip
      largest = std::max(largest, std::acos(std::min(1.0f, d.y)));
    }
  EXPECT_GT(largest, 0.02f);  // the distortion does tilt the fibres somewhere
}

TEST(Material, DeterministicAndSeeded) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p;
  const WoodModel a(block, p, synthesizeGrowthRates(p, block));
  const WoodModel b(block, p, synthesizeGrowthRates(p, block));
  p.seed = 99;
  const WoodModel c(block, p, synthesizeGrowthRates(p, block));
  int differ = 0;
  for (float x = -19; x < 19; x += 0.37f) {
    const glm::vec3 q(x, 0.3f * x, -x);
    EXPECT_EQ(a.evaluate(q).color, b.evaluate(q).color);
    differ += glm::length(a.evaluate(q).color - c.evaluate(q).color) > 1e-3f;
  }
  EXPECT_GT(differ, 20);
}
