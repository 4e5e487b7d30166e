#include "field/growth_rates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "field/bspline.hpp"
#include "model/noise.hpp"
#include "params/parameter_schema.hpp"
#include "util/error.hpp"

namespace kerf {

void GrowthRates::validate() const {
  if (heights < 1 || azimuths < 1 || radii < 1 || heights > 256 || azimuths > 256 || radii > 256) {
    throw InputError("growth-rate grid sizes must be between 1 and 256, got " + std::to_string(heights) +
                     " x " + std::to_string(azimuths) + " x " + std::to_string(radii));
  }
  if (rates.size() != static_cast<std::size_t>(heights) * azimuths * radii) {
    throw InputError("growth-rate grid holds " + std::to_string(rates.size()) + " values, expected " +
                     std::to_string(heights * azimuths * radii));
  }
  if (!std::isfinite(heightMin) || !std::isfinite(heightMax) || (heights > 1 && !(heightMax > heightMin))) {
    throw InputError("growth-rate grid needs a height range with max > min");
  }
  if (!std::isfinite(radiusMin) || !std::isfinite(radiusMax) || radiusMin < 0 || !(radiusMax > radiusMin)) {
    throw InputError("growth-rate grid needs a radius range with 0 <= min < max");
  }
  if (!std::isfinite(azimuthMin) || !std::isfinite(azimuthMax) || !(azimuthMax > azimuthMin) ||
      azimuthMax - azimuthMin > 2.0f * std::numbers::pi_v<float> + 1e-3f) {
    throw InputError("growth-rate grid needs an azimuth range with min < max, at most a full circle");
  }
  for (float r : rates) {
    if (!std::isfinite(r)) throw InputError("growth-rate grid holds a value that is not a finite number");
  }
}

namespace {
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

// x - 2 pi floor(x / 2 pi): written as in GLSL's mod() so the shader gives the same bits.
float wrapTwoPi(float x) {
  return x - kTwoPi * std::floor(x / kTwoPi);
}
}  // namespace

GridStencil gridStencil(const GrowthRates& g, float height, float azimuth) {
  GridStencil s;
  const int nh = g.heights, na = g.azimuths;
  // Heights: clamped B-spline over the levels; constant beyond the first/last level.
  float fh = 0.0f;
  if (nh > 1) {
    fh = (height - g.heightMin) / (g.heightMax - g.heightMin) * (nh - 1);
    fh = std::clamp(fh, 0.0f, static_cast<float>(nh - 1));
  }
  const int ih = std::min(static_cast<int>(fh), nh - 1);
  bsplineWeights<float>(fh - ih, s.heightWeights);
  for (int i = 0; i < 4; ++i) s.heights[i] = std::clamp(ih - 1 + i, 0, nh - 1);

  if (g.fullCircle()) {
    // n_a spokes evenly around the circle from azimuthMin, periodic.
    float fa = wrapTwoPi(azimuth - g.azimuthMin) * (na / kTwoPi);
    fa = std::clamp(fa, 0.0f, static_cast<float>(na));
    const int ia = static_cast<int>(fa);
    bsplineWeights<float>(fa - ia, s.spokeWeights);
    for (int j = 0; j < 4; ++j) {
      int spoke = ia - 1 + j;
      if (spoke < 0) spoke += na;
      while (spoke >= na) spoke -= na;
      s.spokes[j] = spoke;
    }
  } else {
    // n_a spokes from azimuthMin to azimuthMax, clamped like the heights. The angle is taken relative
    // to the range's middle so a range across +-pi works.
    const float mid = 0.5f * (g.azimuthMin + g.azimuthMax), half = 0.5f * (g.azimuthMax - g.azimuthMin);
    const float rel = wrapTwoPi(azimuth - mid + std::numbers::pi_v<float>) - std::numbers::pi_v<float>;
    float fa = na > 1 ? (rel + half) / (2.0f * half) * (na - 1) : 0.0f;
    fa = std::clamp(fa, 0.0f, static_cast<float>(std::max(na - 1, 0)));
    const int ia = std::min(static_cast<int>(fa), na - 1);
    bsplineWeights<float>(fa - ia, s.spokeWeights);
    for (int j = 0; j < 4; ++j) s.spokes[j] = std::clamp(ia - 1 + j, 0, na - 1);
  }
  return s;
}

GrowthRates GrowthRates::uniform(const Block& block, const PithAxis& axis, int heights, int azimuths,
                                 int radii, Azimuths coverage) {
  // Range of heights, radii and azimuths over the block, sampled on a grid (the axis may pass through
  // the block). Azimuths are taken relative to the block centre's, so a range across +-pi works.
  float hLo = std::numeric_limits<float>::max(), hHi = -hLo, rLo = hLo, rHi = 0, aLo = hLo, aHi = -hLo;
  const float centreAzimuth = axis.toCylindrical(glm::vec3(0.0f)).azimuth;
  constexpr int n = 12;
  const glm::vec3 half = block.halfSize();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const glm::vec3 p = -half + 2.0f * half * glm::vec3(i, j, k) / float(n);
        const Cylindrical c = axis.toCylindrical(p);
        hLo = std::min(hLo, c.height), hHi = std::max(hHi, c.height);
        rLo = std::min(rLo, c.radius), rHi = std::max(rHi, c.radius);
        const float rel = std::remainder(c.azimuth - centreAzimuth, kTwoPi);
        aLo = std::min(aLo, rel), aHi = std::max(aHi, rel);
      }
  const float hPad = 0.05f * (hHi - hLo) + 1.0f, rPad = 0.05f * (rHi - rLo) + 1.0f;
  GrowthRates g;
  g.heights = heights, g.azimuths = azimuths, g.radii = radii;
  g.heightMin = hLo - hPad, g.heightMax = hHi + hPad;
  g.radiusMin = std::max(0.0f, rLo - rPad), g.radiusMax = rHi + rPad;
  // A partial range only while the block stays within three quarters of the circle around the axis
  // (an axis through or beside the block sees it all around).
  const float aPad = 0.05f * (aHi - aLo) + 1.0f / std::max(rHi, 1.0f);
  if (coverage == Azimuths::Block && aHi - aLo + 2.0f * aPad < 0.75f * kTwoPi) {
    g.azimuthMin = centreAzimuth + aLo - aPad;
    g.azimuthMax = centreAzimuth + aHi + aPad;
  }
  g.rates.assign(static_cast<std::size_t>(heights) * azimuths * radii, 1.0f);
  return g;
}

GrowthRates synthesizeGrowthRates(const WoodParameters& params, const Block& block) {
  const PithAxis axis = PithAxis::fromAngles(params.pithOrigin, params.pithTilt, params.pithAzimuth);
  GrowthRates g = GrowthRates::uniform(block, axis);
  const std::uint32_t seed = noise::mix(static_cast<std::uint32_t>(params.seed) * 104729u + 7u);
  const float eccentricAngle = params.eccentricityDirection * std::numbers::pi_v<float> / 180.0f;
  const float radialStep = (g.radiusMax - g.radiusMin) / g.radii;
  for (int ih = 0; ih < g.heights; ++ih) {
    const float h =
        g.heights > 1 ? g.heightMin + ih * (g.heightMax - g.heightMin) / (g.heights - 1) : g.heightMin;
    for (int ia = 0; ia < g.azimuths; ++ia) {
      const float theta = g.azimuthMin + ia * 2.0f * std::numbers::pi_v<float> / g.azimuths;
      // Waviness: smooth noise on a circle (periodic in theta) that drifts slowly along the trunk.
      const glm::vec3 q(1.5f * std::cos(theta), 1.5f * std::sin(theta), h / 50.0f);
      for (int ir = 0; ir < g.radii; ++ir) {
        const float r = g.radiusMin + (ir + 0.5f) * radialStep;
        const float years = r / params.ringWidth;
        float width = 1.0f + params.eccentricity * std::cos(theta - eccentricAngle);
        width *= 1.0f + params.irregularity * noise::value1(years * 0.8f, seed);  // wet and dry years
        width *= 1.0f + params.waviness * noise::value3(q + glm::vec3(0, 0, years * 0.05f), seed + 1).x;
        g.at(ih, ia, ir) = 1.0f / std::max(width, 0.05f);  // R is dG/dr: wide rings = low rate
      }
    }
  }
  return g;
}

}  // namespace kerf
