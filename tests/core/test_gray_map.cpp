// The grey map M of Mokume Eq. 5-6 (fit/gray_map.hpp): closed-form fit, peak centres, image loss; and the
// partial azimuth range of fitted growth-rate grids (field/growth_rates.hpp) it works with.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>

#include "field/growth_field.hpp"
#include "fit/gray_map.hpp"
#include "io/project.hpp"
#include "util/error.hpp"

using namespace kerf;

TEST(GrayMap, FitReproducesAPiecewiseLinearMap) {
  // Samples of a map that is itself piecewise linear on the same 16 entries: the fit recovers it.
  GrayMap truth;
  truth.gMin = 2.0, truth.gMax = 10.0;
  for (int i = 0; i < 16; ++i) truth.bar.push_back(0.5 + 0.4 * std::sin(0.9 * i));
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(2.0, 10.0);
  std::vector<double> g{2.0, 10.0}, t;
  for (int i = 0; i < 4000; ++i) g.push_back(u(random));
  for (double x : g) t.push_back(truth.value(x));
  const GrayMap fitted = fitGrayMap(g, t, 16, 1e-9);
  EXPECT_DOUBLE_EQ(fitted.gMin, 2.0);
  EXPECT_DOUBLE_EQ(fitted.gMax, 10.0);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(fitted.bar[i], truth.bar[i], 1e-6) << i;
  EXPECT_NEAR(grayMapImageLoss(fitted, g, t), 0.0, 1e-6);
  // Slope: finite difference inside a segment.
  EXPECT_NEAR(fitted.slope(4.1), (fitted.value(4.1001) - fitted.value(4.0999)) / 0.0002, 1e-4);
  EXPECT_EQ(fitted.slope(1.0), 0.0);  // constant beyond the ends
}

TEST(GrayMap, RidgePullsEmptyEntriesToTheMean) {
  // Samples only near both ends: the middle entries have no data and take the mean target.
  const std::vector<double> g{0.0, 0.01, 0.99, 1.0}, t{0.2, 0.2, 0.6, 0.6};
  const GrayMap m = fitGrayMap(g, t, 11, 1e-3);
  EXPECT_NEAR(m.bar[5], 0.4, 0.05);
  EXPECT_NEAR(m.bar[0], 0.2, 0.02);
  EXPECT_NEAR(m.bar[10], 0.6, 0.02);
}

TEST(GrayMap, PeakCentresAreTheCentresOfBrightRuns) {
  GrayMap m;
  m.gMin = 0, m.gMax = 20;  // 21 entries, one per unit
  m.bar.assign(21, 0.0);
  for (int i : {3, 4, 5}) m.bar[i] = 1.0;  // centre 4
  for (int i : {10}) m.bar[i] = 1.0;       // centre 10
  for (int i : {16, 17}) m.bar[i] = 1.0;   // centre 16.5
  const std::vector<double> c = m.peakCentres();
  ASSERT_EQ(c.size(), 3u);
  EXPECT_DOUBLE_EQ(c[0], 4.0);
  EXPECT_DOUBLE_EQ(c[1], 10.0);
  EXPECT_DOUBLE_EQ(c[2], 16.5);
}

TEST(GrayMap, ARingSplitByOneDarkEntryIsOnePeak) {
  GrayMap m;
  m.gMin = 0, m.gMax = 40;
  m.bar.assign(41, 0.0);
  for (int i : {5, 15, 25, 35}) m.bar[i] = 1.0;
  m.bar[24] = 0.0, m.bar[26] = 1.0;  // ring at 25 split: runs at 25 and... 26 joins 25 (one run 25-26)
  m.bar[27] = 0.0;
  m.bar[14] = 1.0, m.bar[15] = 0.0, m.bar[16] = 1.0;  // ring at 15 split into runs at 14 and 16
  const std::vector<double> c = m.peakCentres();
  ASSERT_EQ(c.size(), 4u);
  EXPECT_DOUBLE_EQ(c[0], 5.0);
  EXPECT_DOUBLE_EQ(c[1], 15.0);  // equal masses: merged halfway
  EXPECT_DOUBLE_EQ(c[2], 25.5);
  EXPECT_DOUBLE_EQ(c[3], 35.0);
}

TEST(GrayMap, RefusesAConstantField) {
  EXPECT_THROW(fitGrayMap({1.0, 1.0, 1.0}, {0.1, 0.2, 0.3}), InputError);
}

TEST(GrowthRatesAzimuths, FarPithGetsThePartOfTheCircleTheBlockFills) {
  const Block block;
  const PithAxis far = PithAxis::fromAngles({0, 0, -300}, 5, 20);
  const GrowthRates partial = GrowthRates::uniform(block, far, 8, 16, 16, GrowthRates::Azimuths::Block);
  ASSERT_FALSE(partial.fullCircle());
  // 40 mm block 280..340 mm from the axis: some 8 degrees plus the margin.
  const float span = (partial.azimuthMax - partial.azimuthMin) * 180.0f / std::numbers::pi_v<float>;
  EXPECT_GT(span, 7.0f);
  EXPECT_LT(span, 14.0f);
  // Every block corner and face centre lies inside the range.
  const float mid = 0.5f * (partial.azimuthMin + partial.azimuthMax);
  for (int i = 0; i < 27; ++i) {
    const glm::vec3 p(-20.0f + 20.0f * (i % 3), -20.0f + 20.0f * (i / 3 % 3), -20.0f + 20.0f * (i / 9));
    const float rel = std::remainder(far.toCylindrical(p).azimuth - mid, 2.0f * std::numbers::pi_v<float>);
    EXPECT_LT(std::abs(rel), 0.5f * (partial.azimuthMax - partial.azimuthMin));
  }
  // The default and an axis through the block keep the full circle.
  EXPECT_TRUE(GrowthRates::uniform(block, far).fullCircle());
  EXPECT_TRUE(GrowthRates::uniform(block, PithAxis{}, 8, 16, 16, GrowthRates::Azimuths::Block).fullCircle());
}

TEST(GrowthRatesAzimuths, PartialGridBendsAcrossTheBlockAndStaysContinuous) {
  const Block block;
  const PithAxis far = PithAxis::fromAngles({0, 0, -300}, 0, 0);
  GrowthRates rates = GrowthRates::uniform(block, far, 4, 16, 16, GrowthRates::Azimuths::Block);
  // Fast growth on one side of the block, slow on the other: with a full-circle grid of 16 spokes the
  // block would sit between two spokes and see almost none of it.
  for (int h = 0; h < rates.heights; ++h)
    for (int a = 0; a < rates.azimuths; ++a)
      for (int r = 0; r < rates.radii; ++r) rates.at(h, a, r) = a < 8 ? 0.95f : 1.05f;
  const GrowthField field(far, 3.0f, rates);
  const float left = field.evaluate(glm::vec3(-19, 0, 0)), right = field.evaluate(glm::vec3(19, 0, 0));
  EXPECT_GT(std::abs(left - right), 3.0f);  // years across the face at equal distance from the pith
  // Continuity along a line across the block, through the whole range and beyond its ends: no jump
  // over 2 um anywhere (the steepest honest slope here is a few years per mm).
  for (float x = -60.0f; x <= 60.0f; x += 0.01f) {
    const float jump = field.evaluate(glm::vec3(x + 0.002f, 0, 0)) - field.evaluate(glm::vec3(x, 0, 0));
    EXPECT_LT(std::abs(jump), 0.02f) << x;
  }
}

TEST(GrowthRatesAzimuths, RangeIsSavedAndOldFilesReadAsFullCircle) {
  const PithAxis far = PithAxis::fromAngles({0, 0, -300}, 0, 0);
  const GrowthRates partial = GrowthRates::uniform(Block{}, far, 2, 4, 3, GrowthRates::Azimuths::Block);
  nlohmann::json json = growthRatesToJson(partial);
  const GrowthRates back = growthRatesFromJson(json);
  EXPECT_FLOAT_EQ(back.azimuthMin, partial.azimuthMin);
  EXPECT_FLOAT_EQ(back.azimuthMax, partial.azimuthMax);
  json.erase("azimuth_range_rad");
  EXPECT_TRUE(growthRatesFromJson(json).fullCircle());
  json["azimuth_range_rad"] = {1.0, 0.5};
  EXPECT_THROW(growthRatesFromJson(json), InputError);
  json["azimuth_range_rad"] = {-4.0, 4.0};  // more than a full circle
  EXPECT_THROW(growthRatesFromJson(json), InputError);
}
