// The knot test bed cut from the spruce log (issue 19 item 3; bench/knot_log_testbed.cpp runs all of it):
// one small block around the bed's live knot, end to end (rendered with the log model, rings detected,
// the growth field and the knot fitted from the photos and the marks), its errors against the log's
// truth held within bounds set from what the bed measured, with margin (docs/knots.md), so that a break
// anywhere in the chain fails here. Where the fit falls short of issue 19's targets the bound says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "knot_log_bed.hpp"
#include "spruce_log.hpp"

using namespace kerf;
using namespace kerf::testing;

// The ring distance on a cut, on fields whose answer is known: planes x = const against planes that lean
// by 0.02 mm per mm of y. A ring's points at height y are 0.02 |y| from the fitted ring through its
// median (y = 0), so the median distance is 0.02 times the median |y| on the cut.
TEST(KnotLogBed, TheHiddenCutMeasuresRingDistancesInMillimetres) {
  const Block block(glm::vec3(40.0f));
  const HiddenCut cut{glm::vec3(0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
  const ScalarField truth = [](const glm::vec3& p) { return p.x / 3.0f; };
  const auto noNear = [](const glm::vec3&) { return false; };
  const CutRingErrors same = cutRingErrors(truth, truth, block, cut, noNear, 0.2f);
  EXPECT_GT(same.points, 1000);
  EXPECT_LT(same.medianMm, 1e-4);
  const ScalarField leaning = [](const glm::vec3& p) { return (p.x + 0.02f * p.y) / 2.0f; };
  const CutRingErrors lean = cutRingErrors(truth, leaning, block, cut, noNear, 0.2f);
  // |y| is uniform on [0, 20] mm over the cut: median 10 mm.
  EXPECT_NEAR(lean.medianMm, 0.02 * 10.0, 0.01);
  EXPECT_EQ(lean.nearPoints, 0);
}

TEST(KnotLogBed, ALiveKnotBlockFromTheSpruceLogIsFittedNearTheTruth) {
  SKIP_WITHOUT_GRAN();
  const LogModel& log = *granLog();
  const std::vector<BedBlockSpec> specs = pickBedBlocks(log);
  const auto live =
      std::find_if(specs.begin(), specs.end(), [](const BedBlockSpec& s) { return s.name == "live"; });
  ASSERT_NE(live, specs.end()) << "the bed's rules found no live knot in the log";
  // Smaller and coarser than the bed's 50 mm at 6.4 px/mm, to run in about ten seconds on one core (the
  // joint pith-and-knot stage's dense solve grows with the contours). At 40 mm every contour lies within
  // the knot's reach and the fit stops ("no ring contours to fit the growth rates to").
  BedBlockSpec spec = *live;
  spec.sizeMm = 45.0f;
  BedRunOptions options;
  options.photos.pxPerMm = 4.0f;
  options.withoutMarks = false;
  options.cutStepMm = 0.2f;
  const BedBlockResult result = runBedBlock(log, spec, true, options);
  ASSERT_EQ(result.knots.size(), 1u);
  const BedKnotResult& k = result.knots[0];
  ASSERT_TRUE(k.fitted) << result.note;
  EXPECT_FALSE(k.deadInBlock);
  std::printf(
      "knot %d, faces %c%c at %.1f deg: axis %.2f deg off, %.2f / %.2f mm off the marks; diameter %.1f / "
      "%.1f mm "
      "(true %.1f / %.1f); rings on the hidden cut %.2f mm median, %.2f near the knot (%d / %d points); pith "
      "%.2f deg, %.2f mm off; %d contours, fit %.1f s\n",
      k.knot, faceLetter(k.faces[0]), faceLetter(k.faces[1]), k.faceAngleDeg, k.axisDeg, k.offsetMm[0],
      k.offsetMm[1], k.fittedDiameterMm[0], k.fittedDiameterMm[1], k.trueDiameterMm[0], k.trueDiameterMm[1],
      k.cut.medianMm, k.cut.medianNearMm, k.cut.points, k.cut.nearPoints, result.pithDeg, result.pithMm,
      result.contours, result.fitSeconds);
  // Measured on this block: axis 1.42 deg, 0.90 / 0.23 mm off the marks (issue 19: 3 deg, 1 mm). Before
  // the marks held the knot (issue 19 item 1): 2.1 deg, 1.46 / 0.22 mm. The marks' default accuracy,
  // 1 mm, is what item 1 guarantees (a little over it: the offset is taken in the face's plane).
  EXPECT_LT(k.axisDeg, 3.0);
  EXPECT_LT(k.offsetMm[0], 1.05);
  EXPECT_LT(k.offsetMm[1], 1.05);
  // Measured with the knot's edges on the photos holding its size (issue 19 item 2): 9.2 / 16.9 mm
  // against 9.8 / 17.8 (-6 %, -5 %); before, 13-17 % of the truth. Issue 19: within 15 %.
  for (int e = 0; e < 2; ++e) {
    EXPECT_GT(k.fittedDiameterMm[e], 0.85 * k.trueDiameterMm[e]);
    EXPECT_LT(k.fittedDiameterMm[e], 1.15 * k.trueDiameterMm[e]);
  }
  // Measured: 0.27 mm median, 0.24 near the knot (with the thin knot of the contours alone 1.34 / 1.18,
  // before the marks held 1.47 / 1.30). Issue 19: 0.5 mm.
  EXPECT_GT(k.cut.nearPoints, 100);
  EXPECT_LT(k.cut.medianMm, 0.5);
  EXPECT_LT(k.cut.medianNearMm, 0.5);
}
