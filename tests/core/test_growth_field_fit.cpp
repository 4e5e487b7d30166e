// The shared growth-field fit pipeline (fit/growth_field_fit.hpp) on a small synthetic block: rendered
// ring-localization images of a known pith axis, pith only and with the growth rates.
#include <gtest/gtest.h>

#include "cn03_sample.hpp"
#include "ring_image_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <numbers>
#include <stop_token>

#include "field/growth_field.hpp"
#include "fit/growth_field_fit.hpp"
#include "io/image.hpp"
#include "params/parameter_schema.hpp"
#include "render/wood_model.hpp"
#include "schema_checks.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace kerf;
using kerf::testing::renderRingImage;

namespace {

struct Sample {
  Block block;
  PithAxis truth = PithAxis::fromAngles({8, 0, -45}, 6, 30);
  GrowthFieldFitInput input;
  Sample() {
    const GrowthField field(truth, 3.0f, GrowthRates::uniform(block, truth));
    for (FaceId f : kAllFaces) input.rings[faceIndex(f)] = renderRingImage(field, block, f, 192, 0.3f);
  }
};

double angleDeg(glm::vec3 a, glm::vec3 b) {
  return std::acos(std::min(1.0, std::abs(double(glm::dot(glm::normalize(a), glm::normalize(b)))))) * 180.0 /
         std::numbers::pi;
}

bool hasLine(const std::vector<ReportLine>& lines, const std::string& start) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const ReportLine& l) { return l.text.rfind(start, 0) == 0; });
}

}  // namespace

TEST(GrowthFieldFit, PithOnlyRecoversTheAxisAndRings) {
  const Sample s;
  GrowthFieldFitOptions options;
  options.pithOnly = true;
  const GrowthFieldFitResult fit = fitGrowthFieldToSample(s.input, s.block, WoodParameters{}, options);
  EXPECT_FALSE(fit.rates);
  const PithAxis axis =
      PithAxis::fromAngles(fit.params.pithOrigin, fit.params.pithTilt, fit.params.pithAzimuth);
  EXPECT_LT(angleDeg(axis.direction, s.truth.direction), 1.0);
  EXPECT_NEAR(fit.params.ringWidth, 3.0, 0.1);
  EXPECT_FALSE(fit.report.distortionsFitted);
  EXPECT_FALSE(fit.report.anatomy);
  for (int n : fit.report.contoursPerFace) EXPECT_GT(n, 0);
  const auto lines = formatGrowthFieldFitReport(fit.report);
  EXPECT_TRUE(hasLine(lines, "contours per face: A "));
  EXPECT_TRUE(hasLine(lines, "pith: O = ("));
  EXPECT_TRUE(hasLine(lines, "anatomy: no face photos"));
  EXPECT_TRUE(hasLine(lines, "ambiguity (Mokume B.1): "));
  EXPECT_TRUE(hasLine(lines, "distortions (Mokume Eq. 4-6) not fitted"));
  EXPECT_TRUE(hasLine(lines, "time: contours "));
}

TEST(GrowthFieldFit, FitsRatesWithRingsAtWholeYears) {
  const Sample s;
  const GrowthFieldFitResult fit = fitGrowthFieldToSample(s.input, s.block, WoodParameters{});
  ASSERT_TRUE(fit.rates);
  EXPECT_NO_THROW(validate(fit.params));
  EXPECT_GT(test::expectOnlyFittedParametersChanged(WoodParameters{}, fit.params, FitBy::Rings), 1);
  EXPECT_EQ(fit.params.ringOffset, 0.0f);
  EXPECT_TRUE(fit.report.distortionsFitted);
  EXPECT_GT(fit.report.ringsAlongFitted, 2);
  EXPECT_LT(fit.report.finalLossRings, 0.2);
  EXPECT_NEAR(fit.report.ringWidthMm, fit.params.ringWidth, 1e-6);
  EXPECT_TRUE(hasLine(formatGrowthFieldFitReport(fit.report), "distortions (Mokume Eq. 4): "));
}

// What the model draws and exports must be the field that was fitted: a procedural grain wobble on top of
// it moved CN03's rings 0.04 ring spacings off the contours (eval_gf.py iso_rel 0.027 -> 0.042).
TEST(GrowthFieldFit, TheModelDrawsTheFittedFieldWithoutAWobble) {
  const Sample s;
  WoodParameters start;
  start.distortionAmplitude = 1.5f;  // a wobbly design the photos are fitted from
  const GrowthFieldFitResult fit = fitGrowthFieldToSample(s.input, s.block, start);
  ASSERT_TRUE(fit.rates);
  EXPECT_EQ(fit.params.distortionAmplitude, 0.0f);
  EXPECT_FLOAT_EQ(fit.report.wobbleRemovedMm, 1.5f);
  EXPECT_TRUE(
      hasLine(formatGrowthFieldFitReport(fit.report), "grain wobble (distortion.amplitude) 1.50 mm -> 0"));
  const WoodModel model(s.block, fit.params, *fit.rates);
  const GrowthField fitted(fit.params, *fit.rates);
  for (float x : {-15.0f, 0.0f, 15.0f})
    for (float y : {-15.0f, 0.0f, 15.0f})
      for (float z : {-15.0f, 0.0f, 15.0f}) {
        const glm::vec3 p(x, y, z);
        EXPECT_NEAR(model.material().year(p), fitted.evaluate(p), 1e-3)
            << "at " << x << ", " << y << ", " << z;
      }
}

TEST(GrowthFieldFit, RefusesTooFewContours) {
  Sample s;
  for (int i = 1; i < 6; ++i) s.input.rings[i] = {};  // face A only
  GrowthFieldFitOptions options;
  options.minContours = 4;
  options.minFaces = 2;
  EXPECT_THROW(fitGrowthFieldToSample(s.input, s.block, WoodParameters{}, options), InputError);
  EXPECT_THROW(fitGrowthFieldToSample(GrowthFieldFitInput{}, s.block, WoodParameters{}), InputError);
}

TEST(GrowthFieldFit, PreviewsResidualsPerContour) {
  const Sample s;
  GrowthFieldFitOptions options;
  std::vector<bool> previewsWithRates;
  options.preview = [&](const WoodParameters& p, const std::optional<GrowthRates>& rates) {
    EXPECT_NO_THROW(validate(p));
    previewsWithRates.push_back(rates.has_value());
  };
  const GrowthFieldFitResult fit = fitGrowthFieldToSample(s.input, s.block, WoodParameters{}, options);
  ASSERT_EQ(previewsWithRates.size(), 2u);  // the undeformed field after the pith, then the result
  EXPECT_FALSE(previewsWithRates[0]);
  EXPECT_TRUE(previewsWithRates[1]);
  int total = 0;
  for (int n : fit.report.contoursPerFace) total += std::max(n, 0);
  ASSERT_EQ(static_cast<int>(fit.contours.size()), total);
  double mean = 0;
  for (const ContourResidual& c : fit.contours) {
    EXPECT_FALSE(c.points.empty());
    EXPECT_FALSE(c.fromTrace);
    EXPECT_GE(c.residualRings, 0.0);
    mean += c.residualRings / total;
  }
  // The same deviations the report's loss averages (per face there, per contour here).
  EXPECT_NEAR(mean, fit.report.finalLossRings, 0.5 * fit.report.finalLossRings + 0.01);
}

TEST(GrowthFieldFit, MokumeSampleCN03ReachesTheAuthorsError) {
  if (!kerf::testing::cn03Available())
    GTEST_SKIP() << "reference data not found at " << kerf::testing::cn03Folder() << " (../shared absent)";
  const GrowthFieldFitInput input = kerf::testing::cn03FitInput();
  const GrowthFieldFitResult fit = fitGrowthFieldToSample(input, Block{}, WoodParameters{});
  for (const ReportLine& line : formatGrowthFieldFitReport(fit.report))
    std::printf("  %s\n", line.text.c_str());
  // The authors' PyTorch fit reaches about 0.032 ring spacings on CN03 (MOKUME_CONVENTIONS.md C); Kerf
  // measured 0.026 with the anatomy prior.
  EXPECT_LT(fit.report.finalLossRings, 0.032);
  EXPECT_LT(fit.report.imageLossAfter, fit.report.imageLossBefore);
  EXPECT_TRUE(fit.report.ringsFromGrayMap);
  EXPECT_EQ(fit.contours.size(), 101u);
  // The pith side is ambiguous on CN03 (rings nearly straight). Its mirrored candidate lies tens of metres
  // away, outside any parameter range: it is reported, not offered as a field.
  EXPECT_TRUE(fit.report.pith.ambiguous);
  if (fit.alternative) {
    EXPECT_TRUE(fit.alternative->rates);
    EXPECT_GT(glm::length(fit.alternative->pith.axis.origin - fit.report.pith.best.axis.origin), 10.0f);
  } else {
    EXPECT_NE(fit.report.alternativeNote.find("outside its allowed range"), std::string::npos)
        << fit.report.alternativeNote;
  }
}

// CN03's two pith candidates are fitted side by side (growth_field_fit.cpp): on one thread or two, the
// same fields bit for bit, and a stop request honoured while both run.
TEST(GrowthFieldFit, TheTwoCandidatesFittedSideBySideGiveTheSameFieldsOnAnyThreadCount) {
  if (!kerf::testing::cn03Available())
    GTEST_SKIP() << "reference data not found at " << kerf::testing::cn03Folder() << " (../shared absent)";
  const GrowthFieldFitInput input = kerf::testing::cn03FitInput();
  const int before = workerThreads();
  setWorkerThreads(1);
  const GrowthFieldFitResult one = fitGrowthFieldToSample(input, Block{}, WoodParameters{});
  setWorkerThreads(2);
  const GrowthFieldFitResult two = fitGrowthFieldToSample(input, Block{}, WoodParameters{});
  setWorkerThreads(before);
  ASSERT_TRUE(one.report.pith.ambiguous);
  ASSERT_TRUE(one.alternative && two.alternative);
  ASSERT_TRUE(one.rates && two.rates && one.alternative->rates && two.alternative->rates);
  EXPECT_EQ(one.rates->rates, two.rates->rates);
  EXPECT_EQ(one.alternative->rates->rates, two.alternative->rates->rates);
  EXPECT_EQ(one.params.pithOrigin, two.params.pithOrigin);
  EXPECT_EQ(one.params.ringWidth, two.params.ringWidth);
  EXPECT_EQ(one.report.finalLossRings, two.report.finalLossRings);
  EXPECT_EQ(one.report.alternativeLossRings, two.report.alternativeLossRings);

  std::stop_source source;
  Progress stopping;
  stopping.stop = source.get_token();
  stopping.report = [&](double f) {
    if (f > 0.6) source.request_stop();  // within the candidates' stage (0.45 .. 0.95)
  };
  EXPECT_THROW(fitGrowthFieldToSample(input, Block{}, WoodParameters{}, {}, stopping), Cancelled);
}

// The pith fit's warnings reach the log as warnings by their stated severity (the CLI prints them to
// stderr, the editor's log marks them), and no other line is one; the text carries no prefix to parse.
TEST(GrowthFieldFit, ReportStatesWhichLinesAreWarnings) {
  GrowthFieldFitReport report;
  report.pith.warnings = {"only 3 contours on face B", "the pith lies far outside the block"};
  const std::vector<ReportLine> lines = formatGrowthFieldFitReport(report);
  std::vector<std::string> warnings;
  for (const ReportLine& line : lines)
    if (line.severity == Severity::Warning) warnings.push_back(line.text);
  EXPECT_EQ(warnings, report.pith.warnings);
  EXPECT_GT(lines.size(), warnings.size());
}
