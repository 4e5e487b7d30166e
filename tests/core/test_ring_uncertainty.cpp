// How sure the fit is (field/ring_uncertainty.hpp, fit/ring_uncertainty_fit.hpp; issue 18 item 4): the
// ring-position spread, the grid's interpolation, its file form, when it is stale, the bootstrap
// replicates, and on a synthetic block seen through Kerf's own photos and detector whether the calibrated
// 1-sigma band holds the true rings about as often as it says.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "field/ring_uncertainty.hpp"
#include "fit/iso_contour_loss.hpp"
#include "fit/ring_uncertainty_fit.hpp"
#include "io/project.hpp"
#include "io/ring_uncertainty_json.hpp"
#include "synthetic_photo_block.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

RingUncertainty rampGrid() {  // sigma = node index i along x, on a 40 mm cube
  RingUncertainty u;
  u.nodes = {5, 3, 2};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 5; ++i) u.sigmaMm.push_back(float(i));
  u.replicates = 8;
  return u;
}

}  // namespace

TEST(RingUncertainty, SpreadIsTheRmsOfWrappedPhaseDifferencesTimesTheSpacing) {
  // Differences +0.1 and -0.1 ring: RMS 0.1 ring; 2 mm spacing: 0.2 mm.
  EXPECT_NEAR(ringPositionSigmaMm(10.3f, 0.0f, {10.4f, 10.2f}, {0.0f, 0.0f}, 2.0f), 0.2f, 1e-5f);
  // A replicate numbering the years one higher, or with a different phase offset, puts the rings in the
  // same places: no spread.
  EXPECT_NEAR(ringPositionSigmaMm(10.3f, 0.0f, {11.3f, 9.3f}, {0.0f, 0.0f}, 2.0f), 0.0f, 1e-5f);
  EXPECT_NEAR(ringPositionSigmaMm(10.3f, 0.2f, {10.5f}, {0.4f}, 2.0f), 0.0f, 1e-5f);
  // Differences wrap to the nearest ring: +0.9 ring is -0.1.
  EXPECT_NEAR(ringPositionSigmaMm(10.0f, 0.0f, {10.9f}, {0.0f}, 1.0f), 0.1f, 1e-5f);
}

TEST(RingUncertainty, InterpolatesTrilinearlyAndClampsOutsideTheBlock) {
  const RingUncertainty u = rampGrid();
  const Block block;  // 40 mm: nodes along x at -20, -10, 0, 10, 20
  EXPECT_NEAR(u.at(block, {-20, 0, 0}), 0.0f, 1e-5f);
  EXPECT_NEAR(u.at(block, {-5, 3, -7}), 1.5f, 1e-5f);
  EXPECT_NEAR(u.at(block, {20, 20, 20}), 4.0f, 1e-5f);
  EXPECT_NEAR(u.at(block, {90, 0, 0}), 4.0f, 1e-5f);
  EXPECT_NEAR(u.quantile(0.5), 2.0f, 1e-5f);
  EXPECT_NEAR(u.quantile(1.0), 4.0f, 1e-5f);
}

TEST(RingUncertainty, RoundTripsThroughJsonAndRefusesBadValues) {
  RingUncertainty u = rampGrid();
  u.field = 0xfedcba9876543210ull;
  u.calibration = 2.5f;
  const RingUncertainty back = ringUncertaintyFromJson(ringUncertaintyToJson(u));
  EXPECT_EQ(back.nodes, u.nodes);
  EXPECT_EQ(back.sigmaMm, u.sigmaMm);
  EXPECT_EQ(back.field, u.field);
  EXPECT_EQ(back.replicates, 8);
  EXPECT_FLOAT_EQ(back.calibration, 2.5f);

  nlohmann::json bad = ringUncertaintyToJson(u);
  bad["sigma_mm"].erase(0);
  try {
    ringUncertaintyFromJson(bad);
    FAIL() << "a grid with a value missing was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("29 values for a grid of 5 x 3 x 2"), std::string::npos) << e.what();
  }
  bad = ringUncertaintyToJson(u);
  bad["sigma_mm"][3] = -1.0;
  EXPECT_THROW(ringUncertaintyFromJson(bad), InputError);
  bad = ringUncertaintyToJson(u);
  bad["field"] = "not hex";
  EXPECT_THROW(ringUncertaintyFromJson(bad), InputError);
  bad = ringUncertaintyToJson(u);
  bad["colour"] = 1;
  EXPECT_THROW(ringUncertaintyFromJson(bad), InputError);
}

TEST(RingUncertainty, BelongsToTheFieldItWasEstimatedFor) {
  Project project;
  project.rates = synthesizeGrowthRates(project.params, project.block);
  RingUncertainty u = rampGrid();
  u.field = fieldFingerprint(project.params, *project.rates, project.knots);
  project.ringUncertainty = u;
  ASSERT_NE(project.currentRingUncertainty(), nullptr);
  // Saved and read back: still the same field.
  const Project back = projectFromJson(projectToJson(project, "/tmp"), "/tmp");
  ASSERT_TRUE(back.ringUncertainty);
  EXPECT_NE(back.currentRingUncertainty(), nullptr);
  // A moved ring or pith makes it stale; a colour does not.
  Project edited = project;
  edited.params.ringOffset += 0.1f;
  EXPECT_EQ(edited.currentRingUncertainty(), nullptr);
  edited = project;
  edited.rates->rates[7] *= 1.01f;
  EXPECT_EQ(edited.currentRingUncertainty(), nullptr);
  edited = project;
  edited.params.pithTilt += 1.0f;
  EXPECT_EQ(edited.currentRingUncertainty(), nullptr);
  edited = project;
  edited.params.earlywoodColor.x *= 0.5f;
  EXPECT_NE(edited.currentRingUncertainty(), nullptr);
}

TEST(RingUncertainty, ReplicatesDrawWholeContoursDeterministically) {
  IsoContours contours;
  for (int c = 0; c < 20; ++c) {
    for (int i = 0; i <= c; ++i) contours.points.push_back({float(c), float(i), 0});
    contours.begin.push_back(static_cast<int>(contours.points.size()));
    contours.face.push_back(c % 2 ? FaceId::A : FaceId::C);
    contours.year.push_back(std::nullopt);
  }
  const IsoContours a = resampledContours(contours, 7), b = resampledContours(contours, 7),
                    other = resampledContours(contours, 8);
  ASSERT_EQ(a.count(), 20);
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, other.points);
  for (int c = 0; c < a.count(); ++c) {  // contour c of the source has c + 1 points, all at x = c
    const int source = static_cast<int>(a.points[a.begin[c]].x);
    EXPECT_EQ(a.size(c), source + 1);
    EXPECT_EQ(a.face[c], source % 2 ? FaceId::A : FaceId::C);
    for (int i = a.begin[c]; i < a.begin[c + 1]; ++i) EXPECT_EQ(a.points[i].x, float(source));
  }
  // With replacement: some contour is drawn twice.
  std::vector<int> drawn(20, 0);
  for (int c = 0; c < a.count(); ++c) ++drawn[static_cast<int>(a.points[a.begin[c]].x)];
  EXPECT_GT(*std::max_element(drawn.begin(), drawn.end()), 1);
}

// The whole chain on a block none of the calibration blocks is (bench/calibrate_ring_uncertainty: its seed
// and pith are not among them): the calibrated band must hold the true rings at about 68 % of the nodes.
// Broad bounds: left out of the calibration in turn, single blocks got 53-92 %; a band half or twice as
// wide as it should be falls outside them.
TEST(RingUncertainty, TheCalibratedBandHoldsTheTrueRingsOnAnUnseenSyntheticBlock) {
  const kerf::testing::SyntheticPhotoBlock b({"keyaki", 11, {-60, 0, -60}, 5, 80});
  const GrowthFieldFitResult fit = fitGrowthFieldToSample(b.input, b.block, b.fitStart, b.options);
  ASSERT_TRUE(fit.rates);
  const RingUncertainty u = estimateRingUncertainty(b.input, b.block, fit, b.options);
  EXPECT_EQ(u.replicates, 8);
  EXPECT_FLOAT_EQ(u.calibration, kRingUncertaintyCalibration);
  EXPECT_EQ(u.field, fieldFingerprint(fit.params, *fit.rates, fit.knots));
  EXPECT_NO_THROW(u.validate());
  const WoodModel truth(b.block, b.truth, b.truthRates);
  const WoodModel fitted(b.block, fit.params, *fit.rates, fit.knots);
  const RingErrorsAtNodes e = ringErrorsAgainstTruth(truth, fitted, u);
  std::printf("median sigma %.3f mm; coverage %.2f (x0.5: %.2f, x2: %.2f)\n", u.quantile(0.5), e.coverage(1),
              e.coverage(0.5f), e.coverage(2.0f));
  EXPECT_GT(u.quantile(0.5), 0.0f);
  EXPECT_GT(e.coverage(1), 0.45);
  EXPECT_LT(e.coverage(1), 0.95);
  EXPECT_LT(e.coverage(0.5f), 0.68);  // half the band: clearly too narrow
  EXPECT_GT(e.coverage(2.0f), 0.68);  // twice the band: clearly too wide
}
