#pragma once
// What a woodworker sees first in a face, as two numbers against the photo (issue 16 item 3): the grain
// direction and the contrast of the rings and detail. The same measures as the shared yardstick
// (../shared/eval/appearance_eval.py `orient` and `contrast`), so the texture inference's objective and
// its report catch what that yardstick catches: pores running across the grain, a washed-out ring figure.
// Scales in px at the yardstick's 6.4 px/mm (Mokume's photos), scaled with the image's own px/mm:
// - Grain direction: the structure tensor of the luminance (gradients after a 1 px blur, averaged over a
//   6 px Gaussian, ~1 mm): per pixel its direction and coherence (0 none, 1 lines).
// - Contrast: the spread of the band-passed luminance (1.5 to 8 px: pores, fibres, ring edges), after each
//   image's own white balance, so a different mean colour does not count.
// - Figure: where the ring figure's light and dark bands lie (luminance band-passed 3 to 16 px, 0.5-2.5
//   mm), compared pixel by pixel: the fitted field puts the rings in place, so a render whose detail
//   drowns the figure (strong fibre streaks, pores spread over the ring) loses this correlation while
//   direction and contrast can still look right. On CN03 from the nara preset, the search without it
//   washed the flat-sawn figure out (docs/texture.md).
// - Streak length: how alike the fine detail (1-8 px: pores, fibres) stays along the grain, as its
//   correlation with itself shifted 1, 2 and 4 mm along the crop's dominant line direction. Long pore
//   streaks (kuri, oak on side grain) stay alike for millimetres, short dashes and speckle do not. Nothing
//   else in the loss sees lengths above ~1 mm: on a synthetic kuri block the search left the pores 3 mm
//   long where they were 10 (docs/texture.md, species round trips).
#include <array>
#include <vector>

#include "io/image.hpp"

namespace kerf {

inline constexpr double kYardstickPxPerMm = 6.4;

struct GrainView {
  int width = 0, height = 0;
  int margin = 12;                 // px left out at the border by the comparisons (the filters' reach)
  std::vector<float> direction;    // per pixel, radians (the dominant gradient's direction)
  std::vector<float> coherence;    // per pixel, 0..1
  double bandSpread = 0;           // standard deviation of the band-passed luminance
  std::vector<float> figure;       // per pixel, the luminance band-passed at the ring figure's scale
  std::array<double, 3> streak{};  // the fine detail's correlation with itself 1, 2 and 4 mm along the lines
};

GrainView grainViewOf(const Image& image, double pxPerMm = kYardstickPxPerMm);

// Agreement of the grain directions, weighted by how clearly each shows one: the correlation of the two
// fields of direction vectors, sum(cp cr cos 2(dp - dr)) / sqrt(sum(cp^2) sum(cr^2)), over the pixels
// the photo's margin inside the border. 1: the same lines in the same directions, as clearly as the photo
// shows them; 0: none or unrelated; -1: across them. Unlike the yardstick's `orient` (divided by sum(cp^2)
// only) it does not grow when the render is more clearly lined than the photo: as an objective, that one made
// the search drop the rays, whose lines cross the rings on end grain. Same size required.
double grainAgreement(const GrainView& render, const GrainView& photo);

// Correlation of the figure bands over the pixels the photo's margin inside the border: 1 the same light and
// dark bands in the same places, 0 unrelated or flat. Same size required.
double figureCorrelation(const GrainView& render, const GrainView& photo);

// bandSpread of the render over the photo's: 1 the same contrast, ~0.1 a flat render.
double contrastRatio(const GrainView& render, const GrainView& photo);

// Mean |difference| of the streak correlations: 0 streaks as long as the photo's, up to 2.
double streakDifference(const GrainView& render, const GrainView& photo);

}  // namespace kerf
