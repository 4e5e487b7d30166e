#pragma once
// Where in its ring the dark detail sits (issue 16 item 3: "where the dark pores sit relative to the ring
// boundary"). Ring-porous wood (oak, chestnut, CN03's kuri) packs its large vessels into a band of
// several rows at the start of the earlywood; diffuse-porous wood spreads them over the ring. Nothing else
// in the texture loss sees that band's width: on CN03 the search traded a band of several rows of pores
// for one row of pores twice as large (latewood share 0.75 -> 0.89, earlywood pore radius 0.12 -> 0.29 mm),
// which the statistics pooled over the face cannot tell apart, and the end grain showed a thin dotted
// line where the photo has a wide band of pores.
//
// The profile: every pixel is labelled by its ring phase under the fitted field (0 at the start of the
// earlywood, 1 at the ring boundary, in `bins` parts; the detail never moves the rings, so the labels hold
// for the photo and every candidate); per part, the mean "dark detail" of the luminance: how much darker a
// pixel is than its surroundings within ~0.5 mm (pores are holes, darker than the wood around them). The
// comparison uses each profile over its own mean, so it judges where the detail sits, not how strong it is
// (the contrast and style terms judge that).
#include <cstdint>
#include <span>
#include <vector>

#include "image/image.hpp"

namespace kerf {

// Per ring-phase part, the summed dark detail and the pixel count of the crops (labels[k] per pixel of
// crops[k], values < bins; the `margin` px border is left out, where the blur reads the mirrored border).
struct RingBandProfile {
  std::vector<double> darkSum;
  std::vector<double> pixels;
  void add(const RingBandProfile& other);
  // The mean dark detail per part over the mean of the parts (1 everywhere: spread evenly); empty when
  // the crops have no dark detail or a part has no pixels.
  std::vector<double> shape() const;
};

RingBandProfile ringBandProfile(const Image& crop, std::span<const std::uint8_t> labels, int bins,
                                double pxPerMm);

// Mean |difference| of the two shapes over the parts: 0 the dark detail in the same parts of the ring, up
// to ~2 (all of it in other parts); 0 when the photo has no dark detail; a render without any is taken as
// spread evenly.
double ringBandDifference(const RingBandProfile& render, const RingBandProfile& photo);

}  // namespace kerf
