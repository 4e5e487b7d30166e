// A knot's edge found on a face photo from its mark (rings/knot_outline.hpp, issue 19 item 2): synthetic
// faces with a known dark ellipse among ring lines, its own lighter knot rings inside, a soft edge and
// camera noise.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <random>

#include "fit/knot_colour_fit.hpp"
#include "rings/knot_outline.hpp"

using namespace kerf;

namespace {

constexpr float kPxPerMm = 6.4f;

struct Ellipse {
  glm::vec2 centre;    // face mm
  glm::vec2 semiAxes;  // mm
  float angleRad = 0;
};

// |p - centre| in units of the ellipse's radius in that direction.
float radiusRatio(const Ellipse& e, glm::vec2 p) {
  const glm::vec2 d = p - e.centre;
  const float c = std::cos(e.angleRad), s = std::sin(e.angleRad);
  const float u = (d.x * c + d.y * s) / e.semiAxes.x, v = (-d.x * s + d.y * c) / e.semiAxes.y;
  return std::sqrt(u * u + v * v);
}

// Face A of a 50 mm cube: light wood with darker ring lines every 3 mm (wavy), and the knot: darker,
// with its own narrow lighter rings (0.4 mm bands) and a 0.3 mm soft edge; Gaussian noise sigma 0.02.
Image knottyFace(const Block& block, const std::optional<Ellipse>& knot, unsigned seed = 7) {
  const glm::vec2 mm = faceSizeMm(block, FaceId::A);
  const int w = static_cast<int>(mm.x * kPxPerMm), h = static_cast<int>(mm.y * kPxPerMm);
  Image out(w, h, 3);
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 0.02f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec2 p = imageToFaceMm(block, FaceId::A, {x + 0.5f, y + 0.5f}, {w, h});
      const float ring = std::fmod(p.y + 1.5f * std::sin(p.x * 0.2f) + 100.0f, 3.0f);
      float v = 0.80f - 0.12f * std::exp(-(ring - 2.5f) * (ring - 2.5f) / 0.08f);
      if (knot) {
        const float q = radiusRatio(*knot, p);
        const float rMm = q * 0.5f * (knot->semiAxes.x + knot->semiAxes.y);
        const float knotWood = 0.52f + 0.06f * (std::fmod(rMm, 0.8f) < 0.4f ? 1.0f : 0.0f);
        const float edge = (q - 1.0f) * 0.5f * (knot->semiAxes.x + knot->semiAxes.y) / 0.3f;  // in 0.3 mm
        const float inside = 1.0f / (1.0f + std::exp(4.0f * edge));
        v = inside * knotWood + (1.0f - inside) * v;
      }
      float* px = out.pixel(x, y);
      const float n = noise(rng);
      px[0] = v + 0.05f + n, px[1] = v + n, px[2] = v - 0.08f + n;
    }
  return out;
}

}  // namespace

TEST(KnotOutline, FindsTheEllipseOfADarkKnotFromAnOffCentreMark) {
  const Block block(glm::vec3(50.0f));
  const Ellipse truth{{22.0f, 27.0f}, {6.0f, 4.0f}, 0.5f};
  const Image photo = knottyFace(block, truth);
  // The user's mark 1 mm off the knot's centre.
  const KnotMark mark{3, FaceId::A, truth.centre + glm::vec2(0.8f, -0.6f)};
  const KnotOutline o = detectKnotOutline(photo, block, mark);
  ASSERT_TRUE(o.found) << o.note;
  EXPECT_EQ(o.knot, 3);
  EXPECT_EQ(o.face, FaceId::A);
  EXPECT_LT(glm::length(o.center - truth.centre), 0.2f);
  EXPECT_NEAR(o.semiAxesMm.x, truth.semiAxes.x, 0.25f);
  EXPECT_NEAR(o.semiAxesMm.y, truth.semiAxes.y, 0.25f);
  // The angle of the long axis, modulo a half turn.
  const float turn = std::remainder(o.angleRad - truth.angleRad, std::numbers::pi_v<float>);
  EXPECT_LT(std::abs(turn), 3.0f * std::numbers::pi_v<float> / 180.0f);
  EXPECT_GE(o.edge.size(), 150u);
  for (glm::vec2 p : o.edge) EXPECT_NEAR(radiusRatio(truth, p), 1.0f, 0.08f);
  EXPECT_LT(o.knotLevel, o.woodLevel - 0.1f);
  EXPECT_NE(o.note.find("rays"), std::string::npos) << o.note;

  // All marks at once, in their order; a face without a photo finds nothing and says so.
  std::array<Image, 6> photos;
  photos[faceIndex(FaceId::A)] = photo;
  const std::vector<KnotOutline> all =
      detectKnotOutlines(photos, block, {mark, KnotMark{3, FaceId::F, {25.0f, 25.0f}}});
  ASSERT_EQ(all.size(), 2u);
  EXPECT_TRUE(all[0].found);
  EXPECT_EQ(all[0].semiAxesMm, o.semiAxesMm);
  EXPECT_FALSE(all[1].found);
  EXPECT_EQ(all[1].note, "no photo of the face");

  // A mark whose edge the user says is wrong gives none, with the reason, though the knot is there.
  KnotMark ignored = mark;
  ignored.ignoreEdge = true;
  const std::vector<KnotOutline> without = detectKnotOutlines(photos, block, {ignored});
  ASSERT_EQ(without.size(), 1u);
  EXPECT_FALSE(without[0].found);
  EXPECT_EQ(without[0].knot, 3);
  EXPECT_NE(without[0].note.find("ignored"), std::string::npos) << without[0].note;
}

TEST(KnotOutline, PlainWoodAtTheMarkIsNoKnot) {
  const Block block(glm::vec3(50.0f));
  const Image photo = knottyFace(block, std::nullopt);
  const KnotOutline o = detectKnotOutline(photo, block, KnotMark{1, FaceId::A, {25.0f, 25.0f}});
  EXPECT_FALSE(o.found);
  EXPECT_TRUE(o.edge.empty());
  EXPECT_FALSE(o.note.empty());
}

TEST(KnotOutline, AKnotAtTheFacesEdgeIsMeasuredFromWhatShowsOrRefusedWithTheReason) {
  const Block block(glm::vec3(50.0f));
  // Centred 1 mm inside the face's left edge, 12 mm across: half the rays find the edge, and the ellipse
  // through them is the knot's.
  const Image half = knottyFace(block, Ellipse{{1.0f, 25.0f}, {6.0f, 6.0f}, 0.0f});
  const KnotOutline o = detectKnotOutline(half, block, KnotMark{1, FaceId::A, {1.0f, 25.0f}});
  ASSERT_TRUE(o.found) << o.note;
  EXPECT_NEAR(o.semiAxesMm.x, 6.0f, 0.4f);  // an ellipse through half its arc: within 7 %
  EXPECT_NEAR(o.semiAxesMm.y, 6.0f, 0.4f);
  EXPECT_LT(glm::length(o.center - glm::vec2(1.0f, 25.0f)), 0.3f);
  // 0.2 mm inside it and 16 mm across: too few rays reach the knot's edge inside the photo.
  const Image most = knottyFace(block, Ellipse{{0.2f, 25.0f}, {8.0f, 8.0f}, 0.0f});
  const KnotOutline edge = detectKnotOutline(most, block, KnotMark{1, FaceId::A, {0.2f, 25.0f}});
  EXPECT_FALSE(edge.found);
  EXPECT_NE(edge.note.find("rays only"), std::string::npos) << edge.note;
  const KnotOutline off = detectKnotOutline(most, block, KnotMark{1, FaceId::A, {-3.0f, 25.0f}});
  EXPECT_FALSE(off.found);
  EXPECT_EQ(off.note, "the mark lies off the photo");
}

// Issue 19 item 4: knots.darkening from the outlines (fit/knot_colour_fit.hpp). The synthetic knot's wood
// is 0.52-0.58 grey (median of its bands about 0.55) in stem wood of 0.80 with darker ring lines: the
// darkening is the wood's colour minus the knot's, about 0.25 in every channel.
TEST(KnotColourFit, TheDarkeningIsTheWoodAroundMinusTheKnotInside) {
  const Block block(glm::vec3(50.0f));
  std::array<Image, 6> photos;
  photos[faceIndex(FaceId::A)] = knottyFace(block, Ellipse{{22.0f, 27.0f}, {6.0f, 4.0f}, 0.5f});
  const KnotOutline o =
      detectKnotOutline(photos[faceIndex(FaceId::A)], block, KnotMark{0, FaceId::A, {22.0f, 27.0f}});
  ASSERT_TRUE(o.found) << o.note;
  const KnotColourFit fit = fitKnotDarkening(photos, block, {o});
  ASSERT_TRUE(fit.fitted) << fit.note;
  EXPECT_EQ(fit.outlines, 1);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(fit.darkening[c], 0.25f, 0.04f) << c;
    EXPECT_FLOAT_EQ(fit.darkening[c], fit.woodColour[c] - fit.knotColour[c]);
  }
  EXPECT_NEAR(fit.woodColour.x - fit.woodColour.z, 0.13f, 0.02f);  // the wood's own tint is kept out

  // No outline found: nothing fitted, and why.
  KnotOutline none = o;
  none.found = false;
  const KnotColourFit nothing = fitKnotDarkening(photos, block, {none});
  EXPECT_FALSE(nothing.fitted);
  EXPECT_EQ(nothing.note, "no knot outline was found on a colour photo");
}
