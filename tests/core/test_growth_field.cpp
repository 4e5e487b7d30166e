// The growth field G (Mokume Sec. 5.2.1): analytic cases, continuity, monotonicity, clamping.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>
#include <random>

#include "field/growth_field.hpp"
#include "params/parameter_schema.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

GrowthRates randomRates(const Block& block, const PithAxis& axis, unsigned seed, float lo, float hi) {
  GrowthRates rates = GrowthRates::uniform(block, axis);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> uniform(lo, hi);
  for (float& r : rates.rates) r = uniform(random);
  return rates;
}

// A point at cylindrical coordinates (h, theta, r) of the axis.
glm::vec3 at(const PithAxis& axis, float h, float theta, float r) {
  return axis.origin + h * axis.direction +
         r * (std::cos(theta) * axis.reference + std::sin(theta) * axis.binormal);
}

}  // namespace

TEST(PithAxis, AnglesAndFrame) {
  const PithAxis straight = PithAxis::fromAngles({0, 0, 0}, 0, 0);
  EXPECT_NEAR(straight.direction.y, 1.0f, 1e-6f);
  const PithAxis tilted = PithAxis::fromAngles({1, 2, 3}, 30, 90);
  EXPECT_NEAR(tilted.direction.y, std::cos(glm::radians(30.0f)), 1e-6f);
  EXPECT_NEAR(tilted.direction.z, -std::sin(glm::radians(30.0f)), 1e-6f);  // azimuth 90 leans towards -z
  for (const PithAxis& a : {straight, tilted, PithAxis::fromDirection({0, 0, 0}, {1, 0, 0}),
                            PithAxis::fromDirection({0, 0, 0}, {0, 0, -1})}) {
    EXPECT_NEAR(glm::dot(a.direction, a.reference), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(a.reference), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(glm::cross(a.reference, a.binormal), a.direction), 1.0f, 1e-6f);
  }
  const Cylindrical c = tilted.toCylindrical(at(tilted, 5.0f, 1.0f, 7.0f));
  EXPECT_NEAR(c.height, 5.0f, 1e-4f);
  EXPECT_NEAR(c.radius, 7.0f, 1e-4f);
  EXPECT_NEAR(c.azimuth, 1.0f, 1e-5f);
  EXPECT_THROW(PithAxis::fromDirection({0, 0, 0}, {0, 0, 0}), InputError);
}

TEST(GrowthField, UndeformedFieldIsDistanceToPithOverRingWidth) {
  const Block block(glm::vec3(40.0f));
  const PithAxis axis = PithAxis::fromAngles({10, 0, -60}, 7, 40);
  const float ringWidth = 2.5f;
  const GrowthField field(axis, ringWidth, GrowthRates::uniform(block, axis));
  std::mt19937 random(3);
  std::uniform_real_distribution<float> coord(-60.0f, 60.0f);
  for (int i = 0; i < 2000; ++i) {  // inside, below the first radial node and beyond the last one
    const glm::vec3 p(coord(random), coord(random), coord(random));
    const float distance = axis.toCylindrical(p).radius;
    EXPECT_NEAR(field.evaluate(p), distance / ringWidth, 1e-4f * (1 + distance))
        << p.x << " " << p.y << " " << p.z;
  }
}

TEST(GrowthField, ConstantRateScalesTheField) {
  const Block block(glm::vec3(40.0f));
  const PithAxis axis = PithAxis::fromAngles({0, 0, -50}, 0, 0);
  GrowthRates rates = GrowthRates::uniform(block, axis);
  for (float& r : rates.rates) r = 2.0f;  // twice the rate: rings half as wide
  const GrowthField field(axis, 3.0f, rates);
  const glm::vec3 p(4, 5, 6);
  EXPECT_NEAR(field.evaluate(p), 2.0f * axis.toCylindrical(p).radius / 3.0f, 1e-4f);
}

// f is continuous at t if the step across t is no larger than the steps just beside it (a jump
// would make the middle step stand out however small the steps are).
template <class F>
void expectContinuousAt(F f, float t, float eps, const char* what) {
  const float across = std::abs(f(t + eps) - f(t - eps));
  const float beside = std::max(std::abs(f(t - eps) - f(t - 3 * eps)), std::abs(f(t + 3 * eps) - f(t + eps)));
  EXPECT_LE(across, 1.5f * beside + 2e-4f) << what << " at " << t;
}

TEST(GrowthField, ContinuousAcrossGridCells) {
  const Block block(glm::vec3(40.0f));
  const PithAxis axis = PithAxis::fromAngles({5, 0, -45}, 10, -20);
  const GrowthRates rates = randomRates(block, axis, 11, 0.3f, 2.5f);
  const GrowthField field(axis, 2.0f, rates);
  const float radialStep = (rates.radiusMax - rates.radiusMin) / rates.radii;
  const float heightStep = (rates.heightMax - rates.heightMin) / (rates.heights - 1);
  for (int ih = 1; ih < rates.heights - 1; ++ih)
    for (int ia = 0; ia < rates.azimuths; ++ia)
      for (int ir = 0; ir <= rates.radii; ++ir) {
        const float h = rates.heightMin + ih * heightStep;
        const float theta = -kPi + (ia + 0.37f) * 2 * kPi / rates.azimuths;
        const float spoke = -kPi + ia * 2 * kPi / rates.azimuths;
        const float r = rates.radiusMin + ir * radialStep;
        expectContinuousAt([&](float t) { return field.evaluate(at(axis, h + 0.3f, theta, t)); }, r, 1e-2f,
                           "radius");
        expectContinuousAt([&](float t) { return field.evaluate(at(axis, t, theta, r + 0.4f)); }, h, 1e-2f,
                           "height");
        expectContinuousAt([&](float t) { return field.evaluate(at(axis, h + 0.3f, t, r + 0.4f)); }, spoke,
                           1e-3f, "azimuth");
      }
  // Across the azimuth seam at +-pi, and the pith is year 0.
  expectContinuousAt([&](float t) { return field.evaluate(at(axis, 1, t, 50)); }, kPi, 1e-3f, "seam");
  EXPECT_NEAR(field.evaluate(at(axis, 0, 0.3f, 0)), 0.0f, 1e-6f);
}

TEST(GrowthField, MonotoneAlongEveryRadiusEvenWithNegativeRates) {
  const Block block(glm::vec3(40.0f));
  const PithAxis axis = PithAxis::fromAngles({0, 0, -40}, 3, 10);
  // Mokume's shipped CN03 has rates below -1 (MOKUME_CONVENTIONS B.2); Kerf clamps them at 0.
  const GrowthRates rates = randomRates(block, axis, 5, -1.5f, 2.0f);
  const GrowthField field(axis, 3.0f, rates);
  for (float h : {-25.0f, -3.0f, 0.0f, 12.0f, 40.0f})
    for (float theta = -kPi; theta < kPi; theta += 0.13f) {
      float previous = -1.0f;
      for (float r = 0.0f; r < rates.radiusMax + 20.0f; r += 0.25f) {
        const float g = field.evaluate(at(axis, h, theta, r));
        EXPECT_GE(g, previous - 1e-4f) << "h=" << h << " theta=" << theta << " r=" << r;
        previous = g;
      }
    }
}

TEST(GrowthField, NegativeRateCellIsFlat) {
  const Block block(glm::vec3(40.0f));
  const PithAxis axis = PithAxis::fromAngles({0, 0, -40}, 0, 0);
  GrowthRates rates = GrowthRates::uniform(block, axis, 1, 1, 4);
  rates.at(0, 0, 2) = -3.0f;
  const GrowthField field(axis, 1.0f, rates);
  const float step = (rates.radiusMax - rates.radiusMin) / 4;
  const float a = field.evaluate(at(axis, 0, 1, rates.radiusMin + 2.1f * step));
  const float b = field.evaluate(at(axis, 0, 1, rates.radiusMin + 2.9f * step));
  EXPECT_NEAR(a, b, 1e-5f);
  const float cumulativeEnd = field.cumulative().back();
  EXPECT_NEAR(cumulativeEnd, rates.radiusMin + 3 * step, 1e-3f);  // three cells of rate 1, one of 0
}

TEST(GrowthField, RejectsBadGrids) {
  const Block block(glm::vec3(40.0f));
  const PithAxis axis = PithAxis::fromAngles({0, 0, -40}, 0, 0);
  GrowthRates rates = GrowthRates::uniform(block, axis);
  rates.rates.pop_back();
  EXPECT_THROW(GrowthField(axis, 1.0f, rates), InputError);
  rates = GrowthRates::uniform(block, axis);
  rates.rates[7] = std::nanf("");
  EXPECT_THROW(GrowthField(axis, 1.0f, rates), InputError);
  rates = GrowthRates::uniform(block, axis);
  EXPECT_THROW(GrowthField(axis, 0.0f, rates), InputError);
  rates.radiusMax = rates.radiusMin;
  EXPECT_THROW(GrowthField(axis, 1.0f, rates), InputError);
}

TEST(GrowthField, SynthesizedRatesFollowTheParameters) {
  const Block block(glm::vec3(40.0f));
  WoodParameters params;
  params.eccentricity = 0, params.irregularity = 0, params.waviness = 0;
  for (float r : synthesizeGrowthRates(params, block).rates) EXPECT_FLOAT_EQ(r, 1.0f);
  params.eccentricity = 0.5f, params.eccentricityDirection = 0;
  const GrowthRates eccentric = synthesizeGrowthRates(params, block);
  // Spoke na/2 sits at azimuth 0, the wide side: rate 1/(1+e); spoke 0 (azimuth -pi) has 1/(1-e).
  EXPECT_NEAR(eccentric.at(0, eccentric.azimuths / 2, 0), 1.0f / 1.5f, 1e-5f);
  EXPECT_NEAR(eccentric.at(0, 0, 0), 1.0f / 0.5f, 1e-5f);
  params.irregularity = 0.4f, params.waviness = 0.2f;
  EXPECT_EQ(synthesizeGrowthRates(params, block).rates, synthesizeGrowthRates(params, block).rates);
  WoodParameters other = params;
  other.seed = 2;
  EXPECT_NE(synthesizeGrowthRates(params, block).rates, synthesizeGrowthRates(other, block).rates);
}

TEST(GrowthField, RingLevels) {
  EXPECT_EQ(ringLevels(0.25f, 0.0f, 3.0f), (std::vector<float>{0.25f, 1.25f, 2.25f}));
  EXPECT_EQ(ringLevels(0.0f, 2.0f, 4.0f), (std::vector<float>{2.0f, 3.0f, 4.0f}));
  EXPECT_TRUE(ringLevels(0.0f, 5.0f, 1.0f).empty());
}
