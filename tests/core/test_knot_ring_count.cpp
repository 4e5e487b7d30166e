// A knot's own rings counted on a face photo (rings/knot_ring_count.hpp, issue 19 item 2): synthetic
// faces with a dark, obliquely cut knot holding a known number of evenly spaced rings, found from a mark
// as the fit finds it (rings/knot_outline.hpp), with camera noise.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rings/knot_outline.hpp"
#include "rings/knot_ring_count.hpp"

using namespace kerf;

namespace {

struct SyntheticKnot {
  glm::vec2 centre{22.0f, 26.0f};  // face mm
  glm::vec2 semiAxes{7.0f, 4.5f};  // mm: an oblique cut
  float angleRad = 0.5f;
  float rings = 9.0f;  // from the centre to the edge; 0: a knot without rings
};

// Face A of a 50 mm cube at pxPerMm: light wood with a few darker ring lines, and the knot: darker, with a
// dark line at the end of each of its years (latewood) and a soft 0.2 mm edge; noise sigma 0.02.
Image knotFace(const Block& block, const SyntheticKnot& k, float pxPerMm, unsigned seed = 3) {
  const glm::vec2 mm = faceSizeMm(block, FaceId::A);
  const int w = static_cast<int>(mm.x * pxPerMm), h = static_cast<int>(mm.y * pxPerMm);
  Image out(w, h, 3);
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 0.02f);
  const float c = std::cos(k.angleRad), s = std::sin(k.angleRad);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec2 p = imageToFaceMm(block, FaceId::A, {x + 0.5f, y + 0.5f}, {w, h});
      const float ring = std::fmod(p.x + 100.0f, 4.0f);
      float v = 0.80f - 0.10f * std::exp(-(ring - 3.5f) * (ring - 3.5f) / 0.1f);
      const glm::vec2 d = p - k.centre;
      const float a = (d.x * c + d.y * s) / k.semiAxes.x, b = (-d.x * s + d.y * c) / k.semiAxes.y;
      const float q = std::sqrt(a * a + b * b);  // 1 on the edge
      const float year = q * k.rings;
      const float phase = year - std::floor(year);
      const float knotWood =
          k.rings > 0 ? 0.55f - 0.10f * std::exp(-(phase - 0.8f) * (phase - 0.8f) / 0.02f) : 0.52f;
      const float edgeMm = (q - 1.0f) * 0.5f * (k.semiAxes.x + k.semiAxes.y);
      const float inside = 1.0f / (1.0f + std::exp(edgeMm / 0.05f));
      v = inside * knotWood + (1.0f - inside) * v;
      float* px = out.pixel(x, y);
      const float n = noise(rng);
      px[0] = v + 0.05f + n, px[1] = v + n, px[2] = v - 0.08f + n;
    }
  return out;
}

KnotRingCount countOn(const Image& photo, const Block& block, const SyntheticKnot& k) {
  KnotMark mark;
  mark.knot = 4;
  mark.face = FaceId::A;
  mark.point = k.centre + glm::vec2(0.6f, -0.4f);  // a user's mark, a little off the centre
  const KnotOutline outline = detectKnotOutline(photo, block, mark);
  EXPECT_TRUE(outline.found) << outline.note;
  return countKnotRings(photo, block, outline);
}

}  // namespace

TEST(KnotRingCount, CountsTheRingsOfAnObliquelyCutKnot) {
  const Block block(glm::vec3(50.0f));
  for (const float rings : {6.0f, 9.0f, 12.0f}) {  // 12: 6 px apart on the short axis
    SyntheticKnot k;
    k.rings = rings;
    const KnotRingCount count = countOn(knotFace(block, k, 16.0f), block, k);
    ASSERT_TRUE(count.found) << rings << " rings: " << count.note;
    EXPECT_EQ(count.knot, 4);
    EXPECT_EQ(count.face, FaceId::A);
    // The outline found lies a little inside the true edge, so the count may come out a little low.
    EXPECT_NEAR(count.rings, rings, 0.08f * rings + 0.3f) << count.note;
    EXPECT_LT(count.sigma, 0.1f * rings) << count.note;
    EXPECT_GT(count.sigma, 0.0f);
  }
}

TEST(KnotRingCount, RingsTooFineForThePhotoAreNotCounted) {
  const Block block(glm::vec3(50.0f));
  SyntheticKnot k;
  k.rings = 30.0f;  // 0.15 mm apart on the short axis: one pixel at 6.4 px/mm
  const KnotRingCount count = countOn(knotFace(block, k, 6.4f), block, k);
  EXPECT_FALSE(count.found) << count.note;
  EXPECT_FALSE(count.note.empty());
  // The same knot at 16 px/mm is still too fine on its short axis (2.4 px per ring): not counted either.
  EXPECT_FALSE(countOn(knotFace(block, k, 16.0f), block, k).found);
  // 14 rings, 5 px apart there: too close to count reliably (some thin lines would be missed), so not
  // counted rather than counted low.
  k.rings = 14.0f;
  const KnotRingCount close = countOn(knotFace(block, k, 16.0f), block, k);
  EXPECT_FALSE(close.found) << close.note;
  EXPECT_NE(close.note.find("too close"), std::string::npos) << close.note;
}

TEST(KnotRingCount, AKnotWithoutRingsGivesNoCount) {
  const Block block(glm::vec3(50.0f));
  SyntheticKnot k;
  k.rings = 0.0f;
  const KnotRingCount count = countOn(knotFace(block, k, 16.0f), block, k);
  EXPECT_FALSE(count.found);
  EXPECT_NE(count.note.find("no rings seen"), std::string::npos) << count.note;
}

TEST(KnotRingCount, NoOutlineOrNoPhotoSaysSo) {
  const Block block(glm::vec3(50.0f));
  KnotOutline missing;
  missing.knot = 2;
  EXPECT_FALSE(countKnotRings(Image(), block, missing).found);
  EXPECT_NE(countKnotRings(Image(), block, missing).note.find("no outline"), std::string::npos);
  KnotOutline found;
  found.found = true;
  found.semiAxesMm = {5, 4};
  found.center = {25, 25};
  EXPECT_NE(countKnotRings(Image(), block, found).note.find("no photo"), std::string::npos);
}
