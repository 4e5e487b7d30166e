#pragma once
// The radial growth-rate grid R of the growth field (Mokume Sec. 5.2.1): n_h heights x n_a azimuths
// x n_r radii. As in the paper, R discretises the radial derivative of the field, here in units of
// 1/growth.ring_width: dG/dr = R / ring_width years per mm. R = 1 everywhere gives rings exactly
// ring_width apart; where R = 2 the rings are half as wide. Negative rates are clamped to 0 when the
// field is built, so the field never folds back on itself.
#include <cstdint>
#include <numbers>
#include <vector>

#include "field/pith_axis.hpp"
#include "geometry/block.hpp"

namespace kerf {

struct WoodParameters;

struct GrowthRates {
  int heights = 8, azimuths = 16, radii = 16;  // n_h, n_a, n_r (Mokume A.2.2 defaults)
  float heightMin = -1, heightMax = 1;         // mm along the pith: the heights of the first/last level
  float radiusMin = 0, radiusMax = 1;          // mm from the pith: the radial cells span this range
  // Radians around the pith. The full circle (the default): n_a spokes evenly around it, blended
  // periodically. A narrower range (a pith far outside the block sees the block under a few degrees,
  // which one spoke in 16 of the full circle could not bend): n_a spokes from azimuthMin to azimuthMax,
  // blended like the heights, constant beyond the ends.
  float azimuthMin = -std::numbers::pi_v<float>, azimuthMax = std::numbers::pi_v<float>;
  std::vector<float> rates;  // heights*azimuths*radii, index (ih*azimuths + ia)*radii + ir

  float& at(int ih, int ia, int ir) {
    return rates[(static_cast<std::size_t>(ih) * azimuths + ia) * radii + ir];
  }
  float at(int ih, int ia, int ir) const {
    return rates[(static_cast<std::size_t>(ih) * azimuths + ia) * radii + ir];
  }

  bool fullCircle() const { return azimuthMax - azimuthMin >= 2.0f * std::numbers::pi_v<float> - 1e-4f; }

  // Throws InputError for bad sizes, empty ranges or non-finite values.
  void validate() const;

  // Which azimuths a new grid spans: the full circle, or (for fitting) just the block as seen from the
  // axis, with a margin; an axis through or close to the block always gets the full circle.
  enum class Azimuths { FullCircle, Block };
  // A uniform grid (all rates 1) whose range covers `block` around `axis`, with a margin.
  static GrowthRates uniform(const Block& block, const PithAxis& axis, int heights = 8, int azimuths = 16,
                             int radii = 16, Azimuths coverage = Azimuths::FullCircle);
};

// Where a point falls in the grid across heights and spokes: the four height levels and four spokes
// whose columns the field blends, with their uniform cubic B-spline weights (field/bspline.hpp).
// The one definition of the blend, used by GrowthField and the distortion fit; the GLSL twin is
// growthStencil() in shaders/wood_model.glsl.
struct GridStencil {
  int heights[4];
  int spokes[4];
  float heightWeights[4];
  float spokeWeights[4];
};
GridStencil gridStencil(const GrowthRates& grid, float height, float azimuth);

// Synthesises plausible growth rates from the growth.* parameters (eccentricity, year-to-year
// irregularity, waviness) and the seed: the procedural way to design wood, and the ground truth of
// the demo block. Deterministic for a given parameter set.
GrowthRates synthesizeGrowthRates(const WoodParameters& params, const Block& block);

}  // namespace kerf
