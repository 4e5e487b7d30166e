// The knot test bed cut from the spruce log (issue 19 item 3; bench/knot_log_testbed.cpp runs all of it):
// one small block around the bed's live knot, end to end (rendered with the log model, rings detected,
// the growth field and the knot fitted from the photos and the marks), its errors against the log's
// truth held within bounds set from what the bed measured, with margin (docs/knots.md), so that a break
// anywhere in the chain fails here. Where the fit falls short of issue 19's targets the bound says so.
#include <gtest/gtest.h>

#include <cstdio>

#include "knot_log_bed.hpp"
#include "spruce_log.hpp"

using namespace kerf;
using namespace kerf::testing;

TEST(KnotLogBed, ALiveKnotBlockFromTheSpruceLogIsFittedNearTheTruth) {
  SKIP_WITHOUT_GRAN();
  const LogModel& log = *granLog();
  const std::vector<BedBlockSpec> specs = pickBedBlocks(log);
  const auto live = std::find_if(specs.begin(), specs.end(), [](const BedBlockSpec& s) { return s.name == "live"; });
  ASSERT_NE(live, specs.end()) << "the bed's rules found no live knot in the log";
  BedBlockSpec spec = *live;
  spec.sizeMm = 40.0f;  // the smallest block the issue allows: the fit's cost grows with the contours
  BedRunOptions options;
  options.withoutMarks = false;
  options.cutStepMm = 0.2f;
  const BedBlockResult result = runBedBlock(log, spec, true, options);
  ASSERT_EQ(result.knots.size(), 1u);
  const BedKnotResult& k = result.knots[0];
  ASSERT_TRUE(k.fitted) << result.note;
  EXPECT_FALSE(k.deadInBlock);
  std::printf(
      "knot %d, faces %c%c at %.1f deg: axis %.2f deg off, %.2f / %.2f mm off the marks; diameter %.1f / %.1f mm "
      "(true %.1f / %.1f); rings on the hidden cut %.2f mm median, %.2f near the knot (%d / %d points); "
      "%d contours, fit %.1f s\n",
      k.knot, faceLetter(k.faces[0]), faceLetter(k.faces[1]), k.faceAngleDeg, k.axisDeg, k.offsetMm[0],
      k.offsetMm[1], k.fittedDiameterMm[0], k.fittedDiameterMm[1], k.trueDiameterMm[0], k.trueDiameterMm[1],
      k.cut.medianMm, k.cut.medianNearMm, k.cut.points, k.cut.nearPoints, result.contours, result.fitSeconds);
  // Issue 19's targets where the bed meets them.
  EXPECT_LT(k.axisDeg, 3.0);
  EXPECT_LT(k.offsetMm[0], 1.0);
  EXPECT_LT(k.offsetMm[1], 1.0);
  // Short of the targets (15 %, 0.5 mm): bounds from the bed's measurements, so that a worse chain fails.
  for (int e = 0; e < 2; ++e) {
    EXPECT_GT(k.fittedDiameterMm[e], 0.1 * k.trueDiameterMm[e]);
    EXPECT_LT(k.fittedDiameterMm[e], 1.15 * k.trueDiameterMm[e]);
  }
  EXPECT_GT(k.cut.nearPoints, 100);
  EXPECT_LT(k.cut.medianMm, 2.0);
  EXPECT_LT(k.cut.medianNearMm, 2.0);
}
