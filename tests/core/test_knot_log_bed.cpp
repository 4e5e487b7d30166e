// The knot test bed cut from the spruce log (issue 19 item 3; bench/knot_log_testbed.cpp runs all of it):
// one small block around the bed's live knot, end to end (rendered with the log model, rings detected,
// the growth field and the knot fitted from the photos and the marks), its errors against the log's
// truth held within bounds set from what the bed measured, with margin (docs/knots.md), so that a break
// anywhere in the chain fails here. Where the fit falls short of issue 19's targets the bound says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

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

namespace {

// One of the bed's blocks (bench/knot_log_testbed.cpp picks them by rule from the log's data), smaller and
// coarser than the bed's 50 mm at 6.4 px/mm, to run in seconds on one core (the knot stages' solves grow
// with the contours, block_knot_fit.cpp). At 40 mm every contour lies
// within the knot's reach and the fit stops ("no ring contours to fit the growth rates to").
BedBlockResult runSmallBedBlock(const LogModel& log, const std::string& name) {
  const std::vector<BedBlockSpec> specs = pickBedBlocks(log);
  const auto found =
      std::find_if(specs.begin(), specs.end(), [&](const BedBlockSpec& s) { return s.name == name; });
  if (found == specs.end()) {
    ADD_FAILURE() << "the bed's rules found no " << name << " knot block in the log";
    return {};
  }
  BedBlockSpec spec = *found;
  spec.sizeMm = 45.0f;
  BedRunOptions options;
  options.photos.pxPerMm = 4.0f;
  options.withoutMarks = false;
  options.cutStepMm = 0.2f;
  return runBedBlock(log, spec, true, options);
}

void printKnot(const BedBlockResult& result, const BedKnotResult& k, double deathYears) {
  std::printf(
      "knot %d, faces %c%c at %.1f deg: axis %.2f deg off, %.2f / %.2f mm off the marks; diameter %.1f / "
      "%.1f mm (true %.1f / %.1f); dead from %.1f years (0: alive); rings on the hidden cut %.2f mm "
      "median, %.2f near the knot (%d / %d points); pith %.2f deg, %.2f mm off; %d contours, fit %.1f s\n",
      k.knot, faceLetter(k.faces[0]), faceLetter(k.faces[1]), k.faceAngleDeg, k.axisDeg, k.offsetMm[0],
      k.offsetMm[1], k.fittedDiameterMm[0], k.fittedDiameterMm[1], k.trueDiameterMm[0], k.trueDiameterMm[1],
      deathYears, k.cut.medianMm, k.cut.medianNearMm, k.cut.points, k.cut.nearPoints, result.pithDeg,
      result.pithMm, result.contours, result.fitSeconds);
}

// Issue 19's targets for the knot itself: its axis within 3 deg, within 1 mm of each mark (the marks'
// default accuracy, which item 1 guarantees; a little over it since the offset is taken in the face's
// plane), its diameter within 15 % at both marked faces.
void expectIssue19Geometry(const BedKnotResult& k) {
  EXPECT_LT(k.axisDeg, 3.0);
  EXPECT_LT(k.offsetMm[0], 1.05);
  EXPECT_LT(k.offsetMm[1], 1.05);
  for (int e = 0; e < 2; ++e) {
    EXPECT_GT(k.fittedDiameterMm[e], 0.85 * k.trueDiameterMm[e]);
    EXPECT_LT(k.fittedDiameterMm[e], 1.15 * k.trueDiameterMm[e]);
  }
}

}  // namespace

TEST(KnotLogBed, ALiveKnotBlockFromTheSpruceLogIsFittedNearTheTruth) {
  SKIP_WITHOUT_GRAN();
  const BedBlockResult result = runSmallBedBlock(*granLog(), "live");
  ASSERT_EQ(result.knots.size(), 1u);
  const BedKnotResult& k = result.knots[0];
  ASSERT_TRUE(k.fitted) << result.note;
  EXPECT_FALSE(k.deadInBlock);
  printKnot(result, k, 0.0);
  // Measured on this block: axis 1.42 deg, 0.90 / 0.23 mm off the marks. Before the marks held the knot
  // (issue 19 item 1): 2.1 deg, 1.46 / 0.22 mm.
  // Measured with the knot's edges on the photos holding its size (issue 19 item 2): 9.2 / 16.9 mm
  // against 9.8 / 17.8 (-6 %, -5 %); before, 13-17 % of the truth.
  expectIssue19Geometry(k);
  // Measured: 0.27 mm median, 0.24 near the knot (with the thin knot of the contours alone 1.34 / 1.18,
  // before the marks held 1.47 / 1.30). Issue 19: 0.5 mm.
  EXPECT_GT(k.cut.nearPoints, 100);
  EXPECT_LT(k.cut.medianMm, 0.5);
  EXPECT_LT(k.cut.medianNearMm, 0.5);
}

// The bed's dead knot (it stopped thickening 39 mm from the pith, inside the block), end to end as above:
// the fit must find that it died (issue 19 item 2: a knot that stops thickening between its edges becomes a
// dead block knot) and place it and the rings around it near the truth.
TEST(KnotLogBed, ADeadKnotBlockFromTheSpruceLogIsFittedNearTheTruth) {
  SKIP_WITHOUT_GRAN();
  const BedBlockResult result = runSmallBedBlock(*granLog(), "dead");
  ASSERT_EQ(result.knots.size(), 1u);
  const BedKnotResult& k = result.knots[0];
  ASSERT_TRUE(k.fitted) << result.note;
  EXPECT_TRUE(k.deadInBlock);
  const auto entry = std::find_if(result.report.knots.begin(), result.report.knots.end(),
                                  [&](const BlockKnotFitEntry& e) { return e.id == k.knot; });
  ASSERT_NE(entry, result.report.knots.end());
  printKnot(result, k, entry->fitted.dead() ? entry->fitted.deathTime : 0.0);
  // Measured on this block (2026-11-29): the knot turned dead at 23.4 years (31.8 mm from the fitted
  // pith, which lies 18.6 mm off the log's; the truth died 39 mm from the log's pith).
  EXPECT_TRUE(entry->fitted.dead()) << entry->note;
  // Measured: axis 0.28 deg, 0.26 / 0.50 mm off the marks; diameter 8.5 / 8.5 mm against 9.0 / 7.7 (-6 %,
  // +10 %): the section frozen at the death, not the 16.9 mm the knot would have reached alive.
  expectIssue19Geometry(k);
  // Measured: 0.49 mm median over the cut (issue 19: 0.5), 0.54 near the knot, short of 0.5 there; the
  // fit before dead block knots (the knot alive, thin) gave 0.61 / 0.56 on the bed's 50 mm block.
  EXPECT_GT(k.cut.nearPoints, 100);
  EXPECT_LT(k.cut.medianMm, 0.55);
  EXPECT_LT(k.cut.medianNearMm, 0.6);
}
