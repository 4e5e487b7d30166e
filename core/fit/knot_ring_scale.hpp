#pragma once
// Each knot's own rings (BlockKnot::ringScale, issue 19 item 2) from their count on the photos.
//
// The knot's surface and axis come from the contours, marks and edges (fit/block_knot_fit.hpp); inside
// it, Eq. 7 alone would show as many rings as the block's field counts years at the surface. The photo's
// count (rings/knot_ring_count.hpp) says how many the branch really has: on each ray, so many dark lines
// from the first to the last. The model's years over exactly those stretches (its G_k there) are compared
// with the photo's rings over them, all rays and faces together; the scale is corrected by their ratio
// (the model's years inside the knot are close to proportional to it) and measured again, four times.
// Faces whose photo shows no countable rings leave the knot's scale as it was (1: Mokume's knot).
#include <array>
#include <string>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "image/image.hpp"
#include "rings/knot_outline.hpp"
#include "rings/knot_ring_count.hpp"

namespace kerf {

struct KnotRingScaleFit {
  int knot = 0;
  std::vector<KnotRingCount> counts;  // one per outline of this knot (found or not: the note says why)
  // Per count found: the model's own rings from the centre to the edge, before and as fitted (the photo's
  // count times the model's years over the photo's years on the same stretches).
  std::vector<float> modelBefore, modelAfter;
  bool fitted = false;
  float ringScale = 1.0f;
  std::string note;
};

// Sets knots[i].ringScale where a knot's rings are counted on at least one face; one entry per knot
// with an outline, in the knots' order.
std::vector<KnotRingScaleFit> fitKnotRingScales(const std::array<Image, 6>& photos, const Block& block,
                                                const GrowthField& stem, const KnotSettings& settings,
                                                std::vector<BlockKnot>& knots,
                                                const std::vector<KnotOutline>& outlines,
                                                const KnotRingCountOptions& options = {});

}  // namespace kerf
