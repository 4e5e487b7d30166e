#pragma once
// The radial growth-rate grid R of the growth field (Mokume Sec. 5.2.1): n_h heights x n_a azimuths
// x n_r radii. As in the paper, R discretises the radial derivative of the field, here in units of
// 1/growth.ring_width: dG/dr = R / ring_width years per mm. R = 1 everywhere gives rings exactly
// ring_width apart; where R = 2 the rings are half as wide. Negative rates are clamped to 0 when the
// field is built, so the field never folds back on itself.
#include <cstdint>
#include <vector>

#include "field/pith_axis.hpp"
#include "geometry/block.hpp"

namespace kerf {

struct WoodParameters;

struct GrowthRates {
  int heights = 8, azimuths = 16, radii = 16;  // n_h, n_a, n_r (Mokume A.2.2 defaults)
  float heightMin = -1, heightMax = 1;         // mm along the pith: the heights of the first/last level
  float radiusMin = 0, radiusMax = 1;          // mm from the pith: the radial cells span this range
  std::vector<float> rates;                    // heights*azimuths*radii, index (ih*azimuths + ia)*radii + ir

  float& at(int ih, int ia, int ir) {
    return rates[(static_cast<std::size_t>(ih) * azimuths + ia) * radii + ir];
  }
  float at(int ih, int ia, int ir) const {
    return rates[(static_cast<std::size_t>(ih) * azimuths + ia) * radii + ir];
  }

  // Throws InputError for bad sizes, empty ranges or non-finite values.
  void validate() const;

  // A uniform grid (all rates 1) whose range covers `block` around `axis`, with a margin.
  static GrowthRates uniform(const Block& block, const PithAxis& axis, int heights = 8, int azimuths = 16,
                             int radii = 16);
};

// Synthesises plausible growth rates from the growth.* parameters (eccentricity, year-to-year
// irregularity, waviness) and the seed: the procedural way to design wood, and the ground truth of
// the demo block. Deterministic for a given parameter set.
GrowthRates synthesizeGrowthRates(const WoodParameters& params, const Block& block);

}  // namespace kerf
