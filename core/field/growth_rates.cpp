#include "field/growth_rates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "material/noise.hpp"
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
  for (float r : rates) {
    if (!std::isfinite(r)) throw InputError("growth-rate grid holds a value that is not a finite number");
  }
}

GrowthRates GrowthRates::uniform(const Block& block, const PithAxis& axis, int heights, int azimuths,
                                 int radii) {
  // Range of heights and radii over the block, sampled on a grid (the axis may pass through the block).
  float hLo = std::numeric_limits<float>::max(), hHi = -hLo, rLo = hLo, rHi = 0;
  constexpr int n = 12;
  const glm::vec3 half = block.halfSize();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const glm::vec3 p = -half + 2.0f * half * glm::vec3(i, j, k) / float(n);
        const Cylindrical c = axis.toCylindrical(p);
        hLo = std::min(hLo, c.height), hHi = std::max(hHi, c.height);
        rLo = std::min(rLo, c.radius), rHi = std::max(rHi, c.radius);
      }
  const float hPad = 0.05f * (hHi - hLo) + 1.0f, rPad = 0.05f * (rHi - rLo) + 1.0f;
  GrowthRates g;
  g.heights = heights, g.azimuths = azimuths, g.radii = radii;
  g.heightMin = hLo - hPad, g.heightMax = hHi + hPad;
  g.radiusMin = std::max(0.0f, rLo - rPad), g.radiusMax = rHi + rPad;
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
      const float theta = -std::numbers::pi_v<float> + ia * 2.0f * std::numbers::pi_v<float> / g.azimuths;
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
