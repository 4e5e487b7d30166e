// A knot's own rings on the photos against the fitted field's years (fit/knot_ring_ages.hpp, issue 19
// item 2): a block rendered from a known field with a thick, dark knot; its own rings counted on its faces
// agree with that field's years, and a field that counts twice the years (half the ring width) is caught.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "demo/demo_block.hpp"
#include "fit/growth_field_fit.hpp"
#include "fit/knot_ring_ages.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "rings/knot_outline.hpp"

using namespace kerf;

namespace {

struct KnottyPhotos {
  Project project;
  std::array<Image, 6> photos;
  std::vector<KnotOutline> outlines;
};

// The demo block with its knot made thick and dark, the rings exactly at whole years of G_k (no waviness),
// its faces rendered at 16 px/mm as the photos, the knot's outlines found from its marks.
const KnottyPhotos& knottyPhotos() {
  static const KnottyPhotos out = [] {
    KnottyPhotos k;
    k.project = demoProject();
    addDemoKnot(k.project);
    k.project.knots[0].speed = 0.16f;
    k.project.params.knotDarkening = glm::vec3(0.3f);
    k.project.params.waviness = 0.0f;
    const WoodModel truth(k.project);
    for (FaceId f : kAllFaces) k.photos[faceIndex(f)] = renderFace(truth, f, {640, 640}, 2);
    k.outlines = detectKnotOutlines(k.photos, k.project.block, k.project.annotations.knots);
    return k;
  }();
  return out;
}

}  // namespace

TEST(KnotRingAges, TheKnotsRingsAgreeWithTheFieldTheBlockWasRenderedFrom) {
  const KnottyPhotos& k = knottyPhotos();
  const WoodModel truth(k.project);
  const std::vector<KnotRingAges> ages =
      compareKnotRings(k.photos, k.project.block, truth.field(), truth.knots(), k.outlines);
  ASSERT_EQ(ages.size(), 1u);
  ASSERT_TRUE(ages[0].counted) << ages[0].note;
  for (const KnotRingAgeFace& f : ages[0].faces) {
    if (!f.count.found) continue;
    // Measured: 13.6 counted against 13.2 years (the render's light rays split a dark line now and then).
    EXPECT_NEAR(f.count.rings, f.fieldCount(), 0.12f * f.fieldCount()) << f.count.note;
    EXPECT_GT(f.count.rings, 8.0f) << f.count.note;
  }
  EXPECT_TRUE(ages[0].agree) << ages[0].note;
  EXPECT_NE(ages[0].note.find("agree"), std::string::npos) << ages[0].note;
}

TEST(KnotRingAges, AFieldThatCountsTwiceTheYearsIsCaught) {
  const KnottyPhotos& k = knottyPhotos();
  // The same field with half the ring width: twice the years everywhere, the knot's rings included.
  WoodParameters halved = k.project.params;
  halved.ringWidth *= 0.5f;
  const WoodModel truth(k.project);
  const GrowthField twice(halved, truth.field().rates());
  const BlockKnots knots(truth.knots().knots(), truth.knots().settings(), halved.ringWidth,
                         twice.axis().direction);
  const std::vector<KnotRingAges> ages =
      compareKnotRings(k.photos, k.project.block, twice, knots, k.outlines);
  ASSERT_EQ(ages.size(), 1u);
  ASSERT_TRUE(ages[0].counted) << ages[0].note;
  EXPECT_FALSE(ages[0].agree) << ages[0].note;
  for (const KnotRingAgeFace& f : ages[0].faces) {
    if (!f.count.found) continue;
    EXPECT_NEAR(f.count.rings / f.fieldCount(), 0.5f, 0.1f) << ages[0].note;
  }
  EXPECT_NE(ages[0].note.find("times the field's years"), std::string::npos) << ages[0].note;
}

TEST(KnotRingAges, NoOutlineNoEntryAndUncountedRingsSaySo) {
  const KnottyPhotos& k = knottyPhotos();
  const WoodModel truth(k.project);
  EXPECT_TRUE(compareKnotRings(k.photos, k.project.block, truth.field(), truth.knots(), {}).empty());
  // Photos too coarse to show the knot's rings: counted on no face, and said so.
  std::array<Image, 6> coarse;
  for (FaceId f : kAllFaces) coarse[faceIndex(f)] = renderFace(truth, f, {80, 80}, 2);
  const std::vector<KnotRingAges> ages =
      compareKnotRings(coarse, k.project.block, truth.field(), truth.knots(), k.outlines);
  ASSERT_EQ(ages.size(), 1u);
  EXPECT_FALSE(ages[0].counted);
  EXPECT_NE(ages[0].note.find("not counted"), std::string::npos) << ages[0].note;
}

TEST(KnotRingAges, TheFitReportSaysWhatWasCounted) {
  const KnottyPhotos& k = knottyPhotos();
  const WoodModel truth(k.project);
  GrowthFieldFitReport report;
  BlockKnotFitEntry entry;
  entry.id = k.project.knots[0].id;
  entry.kept = true;
  report.knots = {entry};
  report.knotRings = compareKnotRings(k.photos, k.project.block, truth.field(), truth.knots(), k.outlines);
  std::string all;
  for (const ReportLine& line : formatGrowthFieldFitReport(report)) all += line.text + "\n";
  EXPECT_NE(all.find("knot 0's own rings on face F: "), std::string::npos) << all;
  EXPECT_NE(all.find("knot 0's own rings: "), std::string::npos) << all;
  EXPECT_NE(all.find("agree with the knot's rings"), std::string::npos) << all;
}
