// The anatomy of the forward model (issue 16 item 2; Liu 2016 Sec. 4.6, Mokume A.2.3): vessels are
// placed without a lattice, run along the fibres (dots on end grain, streaks on long grain), and sit in
// the earlywood of ring-porous wood.
//
// "No lattice" is tested on the 2D power spectrum of the pore weight on cuts at many angles: a lattice
// puts its energy into isolated sharp peaks (spectralPeakRatio). Measured on these cuts with the lattice
// placement of main a26c77b (one pore near the centre of every cell): a strongest peak 116 times the
// power around it; with the jittered placement of kernels/wood.glsl: 8.3.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <opencv2/core.hpp>

#include "render/wood_model.hpp"

using namespace kerf;

namespace {

constexpr int kSize = 256;
constexpr float kPixelMm = 0.05f;

// Pores only, the same everywhere in the year (so the ring does not modulate them), around a straight
// pith along y far from the cuts (the rings are nearly straight there).
WoodParameters poresOnly() {
  WoodParameters p;
  p.pithOrigin = {0, 0, -200};
  p.pithTilt = 0;
  p.ringWidth = 50.0f;
  p.ringColorVariation = 0, p.mottleStrength = 0, p.fiberStrength = 0, p.rayDensity = 0;
  p.distortionAmplitude = 0;
  p.poreRadiusEarly = p.poreRadiusLate = 0.12f;
  p.poreDensityEarly = p.poreDensityLate = 0.7f;
  p.sapwoodStart = 1000;
  return p;
}

GrowthRates uniformRates(const WoodParameters& p, const Block& block) {
  return GrowthRates::uniform(block, PithAxis::fromAngles(p.pithOrigin, p.pithTilt, p.pithAzimuth));
}

// The pore weight on a kSize x kSize cut spanned by u and v (unit vectors) through `centre`.
cv::Mat poreImage(const WoodModel& model, glm::vec3 u, glm::vec3 v, glm::vec3 centre = glm::vec3(0.0f)) {
  cv::Mat image(kSize, kSize, CV_32F);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 p =
          centre + (float(x) - 0.5f * kSize) * kPixelMm * u + (float(y) - 0.5f * kSize) * kPixelMm * v;
      image.at<float>(y, x) = model.evaluate(p).pore;
    }
  return image;
}

// Power spectrum of an image (Hann-windowed, mean removed), DC at (0, 0).
cv::Mat powerSpectrum(const cv::Mat& image) {
  cv::Mat centred = image - cv::mean(image)[0];
  for (int y = 0; y < kSize; ++y)  // no leakage from the image's edges
    for (int x = 0; x < kSize; ++x)
      centred.at<float>(y, x) *=
          float(0.25 * (1 - std::cos(2 * M_PI * x / kSize)) * (1 - std::cos(2 * M_PI * y / kSize)));
  cv::Mat spectrum, power(kSize, kSize, CV_64F);
  cv::dft(centred, spectrum, cv::DFT_COMPLEX_OUTPUT);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const cv::Vec2f c = spectrum.at<cv::Vec2f>(y, x);
      power.at<double>(y, x) = double(c[0]) * c[0] + double(c[1]) * c[1];
    }
  return power;
}

// A lattice shows as isolated sharp peaks in the power spectrum: the strongest frequency (above 4 cycles
// per cut, below which ring-scale shading lives) over the median power of the frequencies around it
// (a 9 x 9 neighbourhood without its 3 x 3 centre). Streaks along the grain concentrate the power along
// one axis, but smoothly, so they do not count as peaks, as a ratio to all frequencies of the same
// radius would. `power` is averaged over parallel cuts, which keeps the random scatter of single
// frequencies small.
double spectralPeakRatio(const cv::Mat& power) {
  double ratio = 0;
  std::vector<double> around;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const int fy = y <= kSize / 2 ? y : y - kSize, fx = x <= kSize / 2 ? x : x - kSize;
      if (std::hypot(fx, fy) < 4) continue;
      around.clear();
      for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx)
          if (std::abs(dx) > 1 || std::abs(dy) > 1)
            around.push_back(power.at<double>((y + dy + kSize) % kSize, (x + dx + kSize) % kSize));
      std::nth_element(around.begin(), around.begin() + around.size() / 2, around.end());
      const double median = around[around.size() / 2];
      if (median > 0) ratio = std::max(ratio, power.at<double>(y, x) / median);
    }
  return ratio;
}

glm::vec3 rotated(glm::vec3 a, glm::vec3 b, float degrees) {
  const float t = glm::radians(degrees);
  return std::cos(t) * a + std::sin(t) * b;
}

}  // namespace

TEST(PoreAnatomy, NoCutAtAnyAngleShowsALattice) {
  const Block block(glm::vec3(40.0f));
  const WoodParameters p = poresOnly();
  const WoodModel model(block, p, uniformRates(p, block));
  // The pith runs along y: x-z cuts are end grain, x-y and z-y cuts long grain; tilt between them.
  const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  double worst = 0;
  std::string worstCut;
  for (float tilt : {0.0f, 20.0f, 45.0f, 70.0f, 90.0f})
    for (float turn : {0.0f, 30.0f, 90.0f}) {
      const glm::vec3 across = rotated(x, z, turn);                      // a direction across the fibres
      const glm::vec3 second = rotated(glm::cross(across, y), y, tilt);  // from across-grain to along-grain
      const glm::vec3 v = glm::normalize(second), normal = glm::cross(across, v);
      cv::Mat power = cv::Mat::zeros(kSize, kSize, CV_64F);
      for (int k = 0; k < 4; ++k) power += powerSpectrum(poreImage(model, across, v, (1.7f * k) * normal));
      const double ratio = spectralPeakRatio(power);
      if (ratio > worst)
        worst = ratio, worstCut = "tilt " + std::to_string(tilt) + ", turn " + std::to_string(turn);
    }
  std::printf("strongest spectral peak / median power around it: %.1f (%s)\n", worst, worstCut.c_str());
  constexpr double kMaxPeakRatio = 20.0;
  EXPECT_LT(worst, kMaxPeakRatio) << "the pores show a lattice on the cut at " << worstCut;
}

namespace {

// Gradient energy across the fibres over gradient energy along them: ~1 for round dots, large for
// streaks along the grain.
double streakiness(const cv::Mat& image) {
  double across = 0, along = 0;
  for (int y = 0; y + 1 < kSize; ++y)
    for (int x = 0; x + 1 < kSize; ++x) {
      const float v = image.at<float>(y, x);
      across += std::pow(image.at<float>(y, x + 1) - v, 2.0f);
      along += std::pow(image.at<float>(y + 1, x) - v, 2.0f);
    }
  return across / std::max(along, 1e-12);
}

}  // namespace

TEST(PoreAnatomy, VesselsAreDotsOnEndGrainAndStreaksAlongTheFibres) {
  const Block block(glm::vec3(40.0f));
  const WoodParameters p = poresOnly();
  const WoodModel model(block, p, uniformRates(p, block));
  // Image rows (v) along the pith (y) on long grain: quarter-sawn (x-y) and flat-sawn (z-y) cuts.
  const double quarter = streakiness(poreImage(model, {1, 0, 0}, {0, 1, 0}));
  const double flat = streakiness(poreImage(model, {0, 0, 1}, {0, 1, 0}));
  const double endGrain = streakiness(poreImage(model, {1, 0, 0}, {0, 0, 1}));
  std::printf("across/along gradient energy: quarter-sawn %.1f, flat-sawn %.1f, end grain %.2f\n", quarter,
              flat, endGrain);
  // A 3 mm vessel of radius 0.12 mm is 12 times longer than wide; allow for the tapered ends.
  EXPECT_GT(quarter, 5.0);
  EXPECT_GT(flat, 5.0);
  EXPECT_NEAR(endGrain, 1.0, 0.35);
}

namespace {

// Ring-porous wood of 3 mm rings around a pith 60 mm off: large pores in the earlywood, few small ones in
// the latewood.
WoodParameters ringPorous(float latewoodFraction, float transition, glm::vec2 radius, glm::vec2 density) {
  WoodParameters p = poresOnly();
  p.ringWidth = 3.0f;
  p.pithOrigin = {0, 0, -60};
  p.latewoodFraction = latewoodFraction, p.transition = transition;
  p.poreRadiusEarly = radius.x, p.poreRadiusLate = radius.y;
  p.poreDensityEarly = density.x, p.poreDensityLate = density.y;
  return p;
}

}  // namespace

TEST(PoreAnatomy, RingPorousWoodPacksItsVesselsInTheEarlywood) {
  const Block block(glm::vec3(40.0f));
  const WoodParameters p = ringPorous(0.6f, 0.1f, {0.14f, 0.03f}, {0.8f, 0.15f});
  const WoodModel model(block, p, uniformRates(p, block));
  double poreEarly = 0, poreLate = 0;
  int early = 0, late = 0;
  for (int y = 0; y < kSize; ++y)  // an end-grain cut
    for (int x = 0; x < kSize; ++x) {
      const WoodSample s =
          model.evaluate({(x - 0.5f * kSize) * kPixelMm, 0.0f, (y - 0.5f * kSize) * kPixelMm});
      (s.latewood < 0.5f ? poreEarly : poreLate) += s.pore;
      ++(s.latewood < 0.5f ? early : late);
    }
  ASSERT_GT(early, 1000);
  ASSERT_GT(late, 1000);
  // Pore area share: density x radius^2 gives ~ 0.8 * 0.14^2 / (0.15 * 0.03^2) ~ 100 times more.
  EXPECT_GT(poreEarly / early, 20.0 * poreLate / late);
}

// pores.earlywood_taper (ring-porous wood opens the year with its largest vessels): on an end-grain cut,
// the pore area in the first third of the earlywood against the last third. Without the taper the two
// are alike; with taper 1 the radius goes from 1.5x to 0.5x the earlywood radius over the earlywood, so the
// first third holds pores of about 1.33x and the last of about 0.67x the radius: some 4x the area.
TEST(PoreAnatomy, TheEarlywoodTaperPutsTheLargestPoresAtTheStartOfTheYear) {
  const Block block(glm::vec3(40.0f));
  WoodParameters p = ringPorous(0.5f, 0.05f, {0.1f, 0.02f}, {0.9f, 0.1f});
  p.poreCellSize = 0.25f;
  const auto thirds = [&](float taper) {
    WoodParameters q = p;
    q.poreEarlyTaper = taper;
    const WoodModel model(block, q, uniformRates(q, block));
    double first = 0, last = 0;
    for (int y = 0; y < 2 * kSize; ++y)
      for (int x = 0; x < 2 * kSize; ++x) {
        const WoodSample s = model.evaluate({(x - kSize) * kPixelMm, 0.0f, (y - kSize) * kPixelMm});
        const float phase = s.year - std::floor(s.year);  // ring offset 0: 0 at the ring line
        if (phase < 0.5f / 3)
          first += s.pore;
        else if (phase > 0.5f * 2 / 3 && phase < 0.5f)
          last += s.pore;
      }
    return first / std::max(last, 1e-9);
  };
  const double even = thirds(0.0f), tapered = thirds(1.0f);
  std::printf("pore area, first over last third of the earlywood: one size %.2f, taper 1 %.2f\n", even,
              tapered);
  EXPECT_NEAR(even, 1.0, 0.25);  // one size: as many pores at the start as at the end
  EXPECT_GT(tapered, 2.5);       // measured 2026-11-29 (see the docs' model.md)
  EXPECT_GT(tapered, 2.0 * even);
}

// The taper reaches the earlywood's pores and nothing else: the latewood's pores, the growth time and the
// latewood share stay bit for bit. (That taper 0 is the model before it, bit for bit, is held by the golden
// images: the demo block has taper 0.)
TEST(PoreAnatomy, TheEarlywoodTaperChangesTheEarlywoodPoresOnly) {
  const Block block(glm::vec3(40.0f));
  const WoodParameters p = ringPorous(0.5f, 0.05f, {0.1f, 0.03f}, {0.9f, 0.5f});
  WoodParameters q = p;
  q.poreEarlyTaper = 0.3f;
  const WoodModel plain(block, p, uniformRates(p, block)), tapered(block, q, uniformRates(q, block));
  int earlywoodChanged = 0, latewood = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 at{(x - 0.5f * kSize) * kPixelMm, 0.0f, (y - 0.5f * kSize) * kPixelMm};
      const WoodSample a = plain.evaluate(at), b = tapered.evaluate(at);
      ASSERT_EQ(a.year, b.year);
      ASSERT_EQ(a.latewood, b.latewood);
      if (a.latewood >= 1.0f) {
        ASSERT_EQ(a.pore, b.pore);
        ++latewood;
      } else if (a.latewood <= 0.0f) {
        earlywoodChanged += a.pore != b.pore;
      }
    }
  EXPECT_GT(latewood, 1000);
  EXPECT_GT(earlywoodChanged, 100);
}
