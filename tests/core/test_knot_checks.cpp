// Knot checks (knots.checks, core/model/kernels/knot_checks.glsl, Kerf's own addition to Larsson et al.
// 2022): the kernel on a knot's cross-section (a few thin radial cracks from near the knot's pith, many and
// open in dead knots, faint in large live ones, none in small live ones or at strength 0, the same for the
// same knot and irregular around it), and the log's and the block's knots that call it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <vector>

#include "field/block_knots.hpp"
#include "field/knot_field.hpp"
#include "model/knot_check_kernels.hpp"
#include "round_log.hpp"

using namespace kerf;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kAlive = std::numeric_limits<float>::infinity();
constexpr float kDark = 0.7f;  // a sample darker than this lies in a crack

// A knot's cross-section sampled on a polar grid: shade[ring][angle], rho = (ring + 0.5) / rings.
struct Section {
  int rings = 200, angles = 1440;
  std::vector<float> shade;
  float at(int ring, int angle) const { return shade[static_cast<std::size_t>(ring) * angles + angle]; }
  int dark() const {
    return static_cast<int>(std::count_if(shade.begin(), shade.end(), [](float v) { return v < kDark; }));
  }
  float darkest() const { return *std::min_element(shade.begin(), shade.end()); }
};

Section section(int knot, float radius, float stemTime, float deathTime, float strength,
                float along = 40.0f) {
  Section s;
  s.shade.resize(static_cast<std::size_t>(s.rings) * s.angles);
  for (int r = 0; r < s.rings; ++r)
    for (int a = 0; a < s.angles; ++a) {
      const float rho = (static_cast<float>(r) + 0.5f) / static_cast<float>(s.rings);
      const float beta = 2.0f * kPi * static_cast<float>(a) / static_cast<float>(s.angles) - kPi;
      s.shade[static_cast<std::size_t>(r) * s.angles + a] =
          knotCheckShade(knot, rho * radius, radius, beta, along, stemTime, deathTime, strength);
    }
  return s;
}

// The cracks of a section: runs of angles (cyclic) whose ring has dark samples in its middle (rho 0.4-0.6
// is crossed by every crack that is open there). Returns each run's middle angle index.
std::vector<int> crackAngles(const Section& s) {
  std::vector<bool> hit(s.angles, false);
  for (int a = 0; a < s.angles; ++a)
    for (int r = s.rings * 2 / 5; r < s.rings * 3 / 5 && !hit[a]; ++r) hit[a] = s.at(r, a) < kDark;
  int first = 0;
  while (first < s.angles && hit[first]) ++first;  // start outside a run
  std::vector<int> out;
  for (int i = 0; i < s.angles; ++i) {
    const int a = (first + i) % s.angles;
    if (!hit[a]) continue;
    int length = 0;
    while (hit[(a + length) % s.angles] && length < s.angles) ++length;
    out.push_back((a + length / 2) % s.angles);
    i += length - 1;
  }
  return out;
}

// Dead: the section 0.3 stem-time units after the death (every crack at full width).
constexpr float kStemTime = 0.5f, kDeathTime = 0.2f;

}  // namespace

TEST(KnotChecks, ADeadKnotHasAFewThinRadialCracks) {
  int knotsWithCracks = 0;
  for (int knot = 0; knot < 12; ++knot) {
    const Section s = section(knot, 8.0f, kStemTime, kDeathTime, 1.0f);
    const std::vector<int> cracks = crackAngles(s);
    knotsWithCracks += !cracks.empty();
    EXPECT_LE(cracks.size(), 5u) << "knot " << knot;
    // Thin: a few per cent of the section at most (not a starburst).
    EXPECT_LT(s.dark(), s.rings * s.angles / 25) << "knot " << knot;
    // Solid at the knot's own pith: no crack starts before 0.05 of its radius.
    for (int r = 0; r < s.rings * 5 / 100; ++r)
      for (int a = 0; a < s.angles; ++a) ASSERT_EQ(s.at(r, a), 1.0f) << "knot " << knot;
    // Radial: each crack's dark samples from rho 0.4 to 0.6 stay within a narrow angle of its middle,
    // so each is a line out from the centre. 0.6 mm of width and wander at rho 0.4 of 8 mm: < 0.2 rad.
    for (const int middle : cracks) {
      int rings = 0;
      for (int r = s.rings * 2 / 5; r < s.rings * 3 / 5; ++r) {
        bool ringHit = false;
        for (int da = -120; da <= 120; ++da) {
          if (!(s.at(r, (middle + da + s.angles) % s.angles) < kDark)) continue;
          ringHit = true;
          EXPECT_LT(std::abs(static_cast<float>(da)) * 2.0f * kPi / static_cast<float>(s.angles), 0.2f)
              << "knot " << knot << " crack at " << middle << " ring " << r;
        }
        rings += ringHit;
      }
      EXPECT_GT(rings, s.rings / 10) << "knot " << knot << ": a crack should run along the radius";
    }
  }
  EXPECT_GE(knotsWithCracks, 10) << "most dead knots show checks";
}

TEST(KnotChecks, StrengthZeroAndOutsideTheKnotLeaveTheColour) {
  for (int knot = 0; knot < 5; ++knot) {
    EXPECT_EQ(section(knot, 8.0f, kStemTime, kDeathTime, 0.0f).dark(), 0);
    EXPECT_EQ(section(knot, 8.0f, kStemTime, kDeathTime, 0.0f).darkest(), 1.0f);
    for (float rho = 1.0f; rho < 3.0f; rho += 0.01f)
      for (float beta = -kPi; beta < kPi; beta += 0.01f)
        ASSERT_EQ(knotCheckShade(knot, rho * 8.0f, 8.0f, beta, 40.0f, kStemTime, kDeathTime, 2.0f), 1.0f);
  }
}

TEST(KnotChecks, LiveKnotsCrackLessAndSmallOnesNot) {
  int deadDark = 0, liveDark = 0;
  for (int knot = 0; knot < 12; ++knot) {
    EXPECT_EQ(section(knot, 2.5f, kStemTime, kAlive, 1.0f).darkest(), 1.0f) << "small live knot " << knot;
    const Section dead = section(knot, 15.0f, kStemTime, kDeathTime, 1.0f);
    const Section live = section(knot, 15.0f, kStemTime, kAlive, 1.0f);
    deadDark += dead.dark(), liveDark += live.dark();
    EXPECT_LE(crackAngles(live).size(), 2u) << "knot " << knot;
    EXPECT_GE(live.darkest(), dead.darkest()) << "knot " << knot;
  }
  EXPECT_GT(deadDark, 0);
  EXPECT_LT(liveDark * 3, deadDark) << "live knots' checks are fainter and fewer";
}

TEST(KnotChecks, DeterministicPerKnotAndIrregular) {
  const Section a = section(7, 8.0f, kStemTime, kDeathTime, 1.0f);
  EXPECT_EQ(a.shade, section(7, 8.0f, kStemTime, kDeathTime, 1.0f).shade);
  int differing = 0;
  std::vector<float> gaps;
  for (int knot = 0; knot < 12; ++knot) {
    const Section s = section(knot, 8.0f, kStemTime, kDeathTime, 1.0f);
    differing += knot != 7 && s.shade != a.shade;
    const std::vector<int> cracks = crackAngles(s);
    for (std::size_t i = 0; i + 1 < cracks.size(); ++i)
      gaps.push_back(static_cast<float>(cracks[i + 1] - cracks[i]) * 360.0f / static_cast<float>(s.angles));
  }
  EXPECT_EQ(differing, 11) << "each knot its own cracks";
  // Irregular around the knot: the angles between neighbouring cracks vary (not a regular star).
  ASSERT_GE(gaps.size(), 10u);
  float mean = 0, var = 0;
  for (const float g : gaps) mean += g / static_cast<float>(gaps.size());
  for (const float g : gaps) var += (g - mean) * (g - mean) / static_cast<float>(gaps.size());
  EXPECT_GT(std::sqrt(var), 10.0f) << "degrees of spread in the gaps between cracks, mean " << mean;
}

// The log (Larsson's field): a dead horizontal knot; its cross-section past the death shows checks in the
// colour, and knots.checks = 0 removes them (and nothing else).
TEST(KnotChecks, TheLogsDeadKnotShowsThemInItsColour) {
  LogModel log = kerf::testing::roundLog();
  log.knots = {kerf::testing::straightKnot(500.0f, 0.0f, 30.0f)};
  KnotSettings on, off;
  off.knotChecks = 0.0f;
  const KnotField withChecks(log, on), without(log, off);
  const WoodColorMap map = woodColorMapFromParameters(WoodParameters{}, 100.0f);
  int cracked = 0, inKnot = 0;
  // The plane x = 60 mm (30 mm past the death) across the knot's axis, 0.05 mm steps.
  for (float y = -8.0f; y <= 8.0f; y += 0.05f)
    for (float z = 492.0f; z <= 508.0f; z += 0.05f) {
      const glm::vec3 p(60.0f, y, z);
      const KnotFieldSample a = withChecks.evaluate(p), b = without.evaluate(p);
      EXPECT_EQ(b.checks, 1.0f);
      EXPECT_EQ(a.time, b.time);
      inKnot += a.knotTime < a.stemTime;
      if (a.checks < kDark) {
        ++cracked;
        EXPECT_LT(a.knotTime, a.stemTime) << "checks only inside the knot";
        const glm::vec3 dark = withChecks.color(a, map), plain = without.color(b, map);
        EXPECT_LT(dark.x + dark.y + dark.z, plain.x + plain.y + plain.z);
      }
    }
  EXPECT_GT(inKnot, 1000);
  EXPECT_GT(cracked, 20);
  EXPECT_LT(cracked * 10, inKnot);
}

// The block's knots: a dead knot's section shows checks in its shade; knots.checks = 0 gives only the bark
// ring's shade; the merged time is unchanged.
TEST(KnotChecks, TheBlocksDeadKnotShowsThemInItsShade) {
  BlockKnot knot;
  knot.id = 3;
  knot.origin = glm::vec3(0.0f);
  knot.direction = glm::vec3(1, 0, 0);
  knot.speed = 0.15f;
  knot.deathTime = 8.0f;  // years; ring width 3 mm: dead from 24 mm, section radius 3.6 mm
  KnotSettings on, off;
  off.knotChecks = 0.0f;
  const BlockKnots withChecks({knot}, on, 3.0f), without({knot}, off, 3.0f);
  int cracked = 0;
  for (float y = -4.0f; y <= 4.0f; y += 0.04f)
    for (float z = -4.0f; z <= 4.0f; z += 0.04f) {
      const glm::vec3 p(45.0f, y, z);
      const float g = 15.0f, r = 45.0f;  // years, mm from the pith axis
      const BlockKnotSample a = withChecks.merge(p, g, r), b = without.merge(p, g, r);
      EXPECT_EQ(a.time, b.time);
      EXPECT_TRUE(b.shade == 1.0f || b.shade == off.knotOutlineShade);
      cracked += a.shade < kDark * b.shade;
      if (std::hypot(y, z) >= 3.6f * 1.001f) {
        EXPECT_EQ(a.shade, b.shade) << y << " " << z;
      }
    }
  EXPECT_GT(cracked, 20);
}
