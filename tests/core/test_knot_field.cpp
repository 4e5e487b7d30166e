// The knot model of Larsson et al. 2022 (core/field/knot_field.hpp): analytic cases for the power smooth
// minimum (Eq. 2-4), adaptive k (4.2.1), the dead-knot factor (4.2.2, Eq. 5), the time fields (Eq. 1) and
// the merge of many knots (Eq. 6), and the random log generator.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "field/knot_field.hpp"
#include "field/log_model.hpp"
#include "round_log.hpp"
#include "util/error.hpp"

using namespace kerf;
using kerf::testing::roundLog;
using kerf::testing::straightKnot;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Settings without noise or slow-down: knot speed = 0.2 x stem speed exactly.
KnotSettings plainSettings() {
  KnotSettings s;
  s.knotSpeed = 0.2f;
  s.knotSpeedDecline = 0.0f;
  s.knotSpeedNoise = 0.0f;
  return s;
}

}  // namespace

TEST(KnotSmoothMin, MatchesEquation2) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> time(0.01f, 2.0f), exponent(0.5f, 12.0f);
  for (int i = 0; i < 200; ++i) {
    const float a = time(rng), b = time(rng), k = exponent(rng);
    const double eq2 = std::pow(
        std::pow(double(a), k) * std::pow(double(b), k) / (std::pow(double(a), k) + std::pow(double(b), k)),
        1.0 / k);
    EXPECT_NEAR(powerSmoothMin(a, b, k), eq2, 1e-5 * eq2) << a << " " << b << " " << k;
    EXPECT_FLOAT_EQ(powerSmoothMin(a, b, k), powerSmoothMin(b, a, k));
    EXPECT_LE(powerSmoothMin(a, b, k), std::min(a, b));
    // Eq. 3: the amount of smoothing is smin - min, never positive (the union pushes rings outward).
    EXPECT_FLOAT_EQ(smoothingAmount(a, b, k), powerSmoothMin(a, b, k) - std::min(a, b));
    EXPECT_LE(smoothingAmount(a, b, k), 0.0f);
  }
  EXPECT_FLOAT_EQ(powerSmoothMin(1.0f, 2.0f, 1.0f), 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(powerSmoothMin(0.5f, 0.5f, 2.0f), 0.5f / std::sqrt(2.0f));
  // At the pith (t = 0) no 0/0: the union is exactly 0.
  EXPECT_EQ(powerSmoothMin(0.0f, 0.7f, 3.0f), 0.0f);
  // Large k approaches the plain minimum; the smoothing grows with the time (Sec. 4.2: "the radius of the
  // union is smaller closer to the pith").
  EXPECT_NEAR(powerSmoothMin(0.3f, 0.4f, 200.0f), 0.3f, 1e-4f);
  EXPECT_LT(std::abs(smoothingAmount(0.1f, 0.15f, 2.0f)), std::abs(smoothingAmount(0.4f, 0.6f, 2.0f)));
}

TEST(KnotSmoothMin, AdaptiveKBlendsBetweenStemAndKnot) {
  KnotSettings s;
  s.knotSmoothStem = 1.5f;
  s.knotSmoothKnot = 5.0f;
  s.knotSmoothTransition = 0.3f;
  EXPECT_FLOAT_EQ(adaptiveK(0.5f, 0.5f, s), 3.25f);     // t_delta = 0: the mean
  EXPECT_NEAR(adaptiveK(10.0f, 0.0f, s), 5.0f, 0.06f);  // deep inside the knot (t_s >> T_b)
  EXPECT_NEAR(adaptiveK(0.0f, 10.0f, s), 1.5f, 0.06f);  // far outside
  float last = 0.0f;
  for (float d = -2.0f; d <= 2.0f; d += 0.05f) {
    const float k = adaptiveK(1.0f + d, 1.0f, s);
    EXPECT_GT(k, last);
    EXPECT_GT(k, s.knotSmoothStem);
    EXPECT_LT(k, s.knotSmoothKnot);
    last = k;
  }
}

TEST(KnotSmoothMin, DeadFactorInvertsWithButterflyWings) {
  KnotSettings s;
  s.knotDeadInversion = -0.5f;
  s.knotDeadTransition = 8.0f;
  s.knotButterfly = 0.6f;
  EXPECT_FLOAT_EQ(deadKnotFactor(0.0f, 0.3f, s), 1.0f);  // continuous with the alive knot at death
  EXPECT_NEAR(deadKnotFactor(5.0f, kPi / 2, s), -0.5f * 1.6f, 1e-5f);   // above the knot: strong wing
  EXPECT_NEAR(deadKnotFactor(5.0f, -kPi / 2, s), -0.5f * 1.6f, 1e-5f);  // below
  EXPECT_NEAR(deadKnotFactor(5.0f, 0.0f, s), -0.5f * 0.4f, 1e-5f);      // at the sides: weak
  EXPECT_NEAR(deadKnotFactor(5.0f, kPi, s), -0.5f * 0.4f, 1e-5f);
  // Monotone from 1 towards the limit with the time since death.
  float last = 2.0f;
  for (float tau = 0.0f; tau < 1.0f; tau += 0.02f) {
    const float f = deadKnotFactor(tau, 1.0f, s);
    EXPECT_LT(f, last);
    last = f;
  }
  s.knotButterfly = 0.0f;
  EXPECT_FLOAT_EQ(deadKnotFactor(0.4f, 0.0f, s), deadKnotFactor(0.4f, kPi / 2, s));
}

TEST(KnotSmoothMin, WindowHasCompactSupport) {
  KnotSettings s;
  s.knotReachStart = 0.4f;
  s.knotReachEnd = 0.8f;
  EXPECT_EQ(knotWindow(0.0f, s), 1.0f);
  EXPECT_EQ(knotWindow(0.4f, s), 1.0f);
  EXPECT_NEAR(knotWindow(0.6f, s), 0.5f, 1e-6f);
  EXPECT_EQ(knotWindow(0.8f, s), 0.0f);
  EXPECT_EQ(knotWindow(3.0f, s), 0.0f);
}

TEST(KnotTimeField, StemTimeIsDistanceOverRadius) {
  LogModel log = roundLog();
  for (glm::vec2& p : log.stem.pith) p = glm::vec2(10.0f, -5.0f);
  const KnotField field(log, plainSettings());
  EXPECT_NEAR(field.evaluate({60.0f, -5.0f, 300.0f}).time, 0.5f, 1e-6f);  // Eq. 1: 50 mm / 100 mm
  EXPECT_NEAR(field.evaluate({10.0f, 25.0f, 300.0f}).time, 0.3f, 1e-6f);
  EXPECT_EQ(field.evaluate({10.0f, -5.0f, 300.0f}).time, 0.0f);  // on the pith
  // The radius varies with azimuth: radius 50 towards +y (azimuth 90 deg) halves the speed there.
  LogModel oval = roundLog();
  for (int i = 0; i < oval.stem.slices(); ++i) oval.stem.radii[i * 36 + 9] = 50.0f;
  const KnotField ovalField(oval, plainSettings());
  EXPECT_NEAR(ovalField.evaluate({0.0f, 25.0f, 300.0f}).time, 0.5f, 1e-6f);
  EXPECT_NEAR(ovalField.evaluate({25.0f, 0.0f, 300.0f}).time, 0.25f, 1e-6f);
}

TEST(KnotTimeField, KnotTimeIsDistanceToThePseudoNearestPointOverKnotSpeed) {
  LogModel log = roundLog();
  log.knots.push_back(straightKnot(500.0f, 0.0f));
  const KnotSettings s = plainSettings();
  const KnotField field(log, s);
  // 50 mm from the pith along the knot's azimuth, 10 mm above it: d_b = 10, speed 0.2 x 100 mm -> T_b = 0.5.
  const KnotFieldSample above = field.evaluate({50.0f, 0.0f, 510.0f});
  EXPECT_NEAR(above.stemTime, 0.5f, 1e-6f);
  EXPECT_NEAR(above.knotTime, 0.5f, 1e-6f);
  // Sideways (tangentially) the pseudo-nearest point is at the same distance from the pith: a chord.
  const float angle = 0.1f;
  const KnotFieldSample side = field.evaluate({50.0f * std::cos(angle), 50.0f * std::sin(angle), 500.0f});
  EXPECT_NEAR(side.knotTime, 2.0f * 50.0f * std::sin(angle / 2) / 20.0f, 1e-5f);
  // Outside the knot, one knot: Eq. 6 reduces to t = t_s + delta (Eq. 3-4) with the adaptive k.
  const KnotFieldSample outside = field.evaluate({50.0f, 0.0f, 515.0f});
  EXPECT_NEAR(outside.knotTime, 0.75f, 1e-6f);
  EXPECT_NEAR(outside.time, 0.5f + smoothingAmount(0.5f, 0.75f, adaptiveK(0.5f, 0.75f, s)), 1e-6f);
  EXPECT_LT(outside.time, outside.stemTime);  // rings bulge outward around an alive knot
  // Inside the knot the time is the knot's own (its rings), nearly undistorted.
  const KnotFieldSample inside = field.evaluate({50.0f, 0.0f, 502.0f});
  EXPECT_NEAR(inside.knotTime, 0.1f, 1e-6f);
  EXPECT_NEAR(inside.time, 0.1f, 0.01f);
  EXPECT_GT(inside.darkness, 0.99f);
  EXPECT_EQ(outside.darkness, 0.0f);
}

TEST(KnotTimeField, DeadKnotStopsGrowingAndInvertsTheFillet) {
  LogModel log = roundLog();
  log.knots.push_back(straightKnot(500.0f, 0.0f, 30.0f));  // dies 30 mm from the pith: t_death = 0.3
  const KnotSettings s = plainSettings();
  const KnotField field(log, s);
  // 15 mm above the knot at d = 50: alive T_b = 0.75, tau = 0.5 - 0.3 = 0.2, T_b' = 0.95 (Eq. 5).
  const KnotFieldSample p = field.evaluate({50.0f, 0.0f, 515.0f});
  const float tau = 0.2f, tb = 0.95f;
  const float k = adaptiveK(0.5f, 0.75f, s) + s.knotDeadSharpening * tau;
  const float delta = deadKnotFactor(tau, kPi / 2, s) * smoothingAmount(0.5f, tb, k);
  EXPECT_NEAR(p.knotTime, tb, 1e-5f);
  EXPECT_NEAR(p.time, 0.5f + delta, 1e-6f);
  EXPECT_GT(p.time, p.stemTime);  // inverted: the rings are pulled in towards the dead knot
  // The dead knot keeps its cross-section: once the stem has grown well past the death, its edge
  // (T_b' = t_s) lies at d_b = speed x t_death x r_s = 6 mm.
  for (float d : {60.0f, 75.0f, 90.0f}) {
    EXPECT_LT(field.evaluate({d, 0.0f, 505.8f}).knotTime, field.evaluate({d, 0.0f, 505.8f}).stemTime) << d;
    EXPECT_GT(field.evaluate({d, 0.0f, 506.2f}).knotTime, field.evaluate({d, 0.0f, 506.2f}).stemTime) << d;
  }
  EXPECT_GT(field.evaluate({60.0f, 0.0f, 502.0f}).deadShade, 0.0f);
  EXPECT_EQ(field.evaluate({20.0f, 0.0f, 501.0f}).deadShade, 0.0f);  // before death: alive knot wood
}

TEST(KnotTimeField, ManyKnotsAddTheirSmoothingAmounts) {
  LogModel log = roundLog();
  log.knots.push_back(straightKnot(500.0f, 0.0f));
  log.knots.push_back(straightKnot(530.0f, 0.0f));
  const KnotSettings s = plainSettings();
  const KnotField field(log, s);
  // Between the knots, 50 mm out: 14 mm from the lower, 16 mm from the upper knot (ratios below reach_start).
  const KnotFieldSample p = field.evaluate({50.0f, 0.0f, 514.0f});
  const float t1 = 14.0f / 20.0f, t2 = 16.0f / 20.0f;
  const float expected = 0.5f + smoothingAmount(0.5f, t1, adaptiveK(0.5f, t1, s)) +
                         smoothingAmount(0.5f, t2, adaptiveK(0.5f, t2, s));  // Eq. 6
  EXPECT_NEAR(p.time, expected, 1e-6f);
  EXPECT_EQ(p.knotsInReach, 2);
  // Order does not matter (Sec. 4.2.3).
  LogModel swapped = log;
  std::swap(swapped.knots[0], swapped.knots[1]);
  EXPECT_NEAR(KnotField(swapped, s).evaluate({50.0f, 0.0f, 514.0f}).time, p.time, 1e-6f);
}

TEST(KnotTimeField, KnotsOutOfReachChangeNothing) {
  LogModel log = roundLog();
  log.knots.push_back(straightKnot(500.0f, 0.0f));
  const KnotSettings s = plainSettings();
  const KnotField field(log, s);
  // 50 mm out, 41 mm above: d_b / d_s = 0.82 >= reach_end = 0.8.
  const KnotFieldSample p = field.evaluate({50.0f, 0.0f, 541.0f});
  EXPECT_EQ(p.time, p.stemTime);
  EXPECT_EQ(p.knotsInReach, 0);
  EXPECT_EQ(p.darkness, 0.0f);
  // Opposite side of the pith.
  EXPECT_EQ(field.evaluate({-50.0f, 0.0f, 500.0f}).knotsInReach, 0);
}

TEST(KnotTimeField, CullKeepsEveryKnotThatReaches) {
  const LogModel log = generateRandomLog({.seed = 3, .lengthMm = 1200.0f, .radiusMm = 110.0f});
  const KnotField field(log, KnotSettings{});
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> xy(-120.0f, 120.0f), z(0.0f, 1200.0f), extent(0.5f, 30.0f);
  int culledSomething = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const glm::vec3 lo(xy(rng), xy(rng), z(rng));
    const glm::vec3 hi = lo + glm::vec3(extent(rng), extent(rng), extent(rng));
    std::vector<int> kept;
    field.cull(lo, hi, field.allKnots(), kept);
    culledSomething += kept.size() < log.knots.size();
    // Every point of the box: a knot that is in reach there was kept.
    for (int s = 0; s < 20; ++s) {
      std::uniform_real_distribution<float> u(0.0f, 1.0f);
      const glm::vec3 p = lo + (hi - lo) * glm::vec3(u(rng), u(rng), u(rng));
      for (int k = 0; k < static_cast<int>(log.knots.size()); ++k) {
        const int one[] = {k};
        if (field.evaluate(p, one).knotsInReach > 0) {
          EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), k))
              << "knot " << k << " culled but in reach";
        }
      }
    }
  }
  EXPECT_GT(culledSomething, 250);
}

TEST(RandomLog, DeterministicAndPlausible) {
  const RandomLogOptions options{.seed = 42};
  const LogModel a = generateRandomLog(options), b = generateRandomLog(options);
  ASSERT_EQ(a.knots.size(), b.knots.size());
  EXPECT_EQ(a.stem.radii, b.stem.radii);
  for (std::size_t i = 0; i < a.knots.size(); ++i) EXPECT_EQ(a.knots[i].heights, b.knots[i].heights);
  const LogModel c = generateRandomLog({.seed = 43});
  EXPECT_NE(a.stem.radii, c.stem.radii);
  EXPECT_NO_THROW(validate(a));
  // Whorls: several knots within a few cm of each other, every few hundred mm.
  ASSERT_GE(a.knots.size(), 8u);
  int alive = 0, dead = 0;
  for (const Knot& k : a.knots) {
    EXPECT_GT(k.heights.back(), k.heights.front()) << "branches rise outward";
    (std::isfinite(k.deathDistance) ? dead : alive)++;
  }
  EXPECT_GT(dead, 0) << "some knots turn dead";
  float bend = 0.0f;
  for (const glm::vec2& p : a.stem.pith) bend = std::max(bend, std::abs(p.x) + std::abs(p.y));
  EXPECT_GT(bend, 1.0f) << "the pith is curved";
  EXPECT_THROW(generateRandomLog({.seed = 1, .lengthMm = 5.0f}), InputError);
}

TEST(RandomLog, KnottiestHeightFindsTheWhorl) {
  LogModel log = roundLog();
  EXPECT_FLOAT_EQ(knottiestHeight(log, 100.0f), 500.0f);  // no knots: the middle
  for (float z : {200.0f, 610.0f, 620.0f, 630.0f, 900.0f}) log.knots.push_back(straightKnot(z, 0.0f));
  const float z = knottiestHeight(log, 100.0f);
  EXPECT_GE(z, 580.0f);
  EXPECT_LE(z, 660.0f);
}
