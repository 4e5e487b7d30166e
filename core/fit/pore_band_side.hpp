#pragma once
// Which side of the block the pith lies on, as the pores tell it (issue 18 item 3). The ring contours
// fix where the rings are but barely how they curve: on a 40 mm block the pith and its mirror image
// through the block (Mokume Appendix B.1) explain them almost equally well, and the years then run the
// wrong way. Ring-porous wood (chestnut, oak, elm, keyaki) settles it: each year starts with a band of
// large earlywood vessels, so the pores lie just after each ring boundary on the pith's side of the ring
// (Liu 2016 Sec. 4.2: the ring phase runs 0 at the start of the earlywood to 1 at the ring boundary).
// Under the right pith the photos' dark detail (fit/ring_band_profile.hpp) sits early in the ring phase;
// under the mirrored one, late.
#include <array>
#include <optional>
#include <vector>

#include "field/growth_field.hpp"
#include "geometry/block.hpp"
#include "image/image.hpp"
#include "params/parameter_schema.hpp"

namespace kerf {

// Whether the species' wood is ring-porous: large earlywood pores (>= 0.05 mm) more than three times
// the latewood's (kuri 0.125/0.035, nara 0.132/0.015; not walnut 0.072/0.042, nor the defaults' 3:1).
bool isRingPorous(const WoodParameters& params);

struct PoreBandPlacement {
  std::vector<double> shape;  // dark detail per tenth of the ring phase over the mean (ring_band_profile)
  // Mean shape over the first three tenths minus the mean over the last three: > 0 the dark detail opens
  // the rings (ring-porous wood seen from the right pith), < 0 it closes them. 0 without dark detail.
  double earlyMinusLate = 0;
};

// The photos' dark detail by ring phase of the fitted field (rings at G = ringOffset + k), over every face
// with a photo (empty faces skipped).
PoreBandPlacement poreBandPlacement(const GrowthField& field, float ringOffset, const Block& block,
                                    const std::array<Image, 6>& photos);

// Where the earlywood begins, as the pores show it (ring-porous wood): the shift of the ring phase (years,
// in [-0.5, 0.5)) that brings the start of the earlywood to the start of the `bandShare`-wide part of the
// ring phase holding the most dark detail in the photos, measured under rings at G = ringOffset + k; the
// ring offset that draws the pores where the photos have them is ringOffset + the shift. The ring maps'
// lines run through the middle of the dark pore band (CN03: the band reaches a tenth of a year before
// them), while the model's year starts with its pores. nullopt without dark detail.
std::optional<double> poreBandStart(const GrowthField& field, float ringOffset, const Block& block,
                                    const std::array<Image, 6>& photos, double bandShare);

// A shift larger than this is not the same band (the pores of the ring before or after): kept out.
inline constexpr double kMaxEarlywoodShift = 0.25;

// How clearly the pores must open the rings under one pith and close them under the other before they
// overrule the contours' choice (CN03: +0.59 against -0.56).
inline constexpr double kPoreBandSideMargin = 0.2;

}  // namespace kerf
