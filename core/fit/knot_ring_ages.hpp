#pragma once
// What a knot's own rings say about the fitted field's years (issue 19 item 2; issue 18 item 3, how old
// the wood is): a measurement reported with the fit, not a fitted parameter.
//
// A knot's rings are the branch's years, the same growth layers as the stem's rings they join at the
// knot's surface (Larsson et al. 2022 Sec. 4.1), so across a knot cut by a face the photo shows as many
// rings as the tree grew between the branch's pith and that face. The fitted field (Mokume Eq. 7) counts
// them as its own years: the block's ring width extrapolated to the pith. The photo's count
// (rings/knot_ring_count.hpp: so many dark lines from the first to the last on each ray) is compared with
// the field's years over exactly those stretches of the same rays. They differ where the rings between
// the pith and the block were wider or narrower than the block's own (then the field's age of the wood
// is off), or where the ring detection counted two lines per year; between two faces of one knot the
// photo's rings and the field's years must grow alike, since they are the same layers.
//
// Why not fit the knot's rings to the count: scaling them inside the knot (tried, docs/knots.md "The
// knot's own rings") gives one growth layer different years at different distances along the knot,
// which the rings on the bed's hidden cuts punished (0.29 -> 0.71 mm on the live block).
#include <array>
#include <string>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "image/image.hpp"
#include "rings/knot_outline.hpp"
#include "rings/knot_ring_count.hpp"

namespace kerf {

struct KnotRingAgeFace {
  KnotRingCount count;    // the photo's count on this face (found or not: its note says why)
  double photoRings = 0;  // found: the photo's rings over its stretches (dark lines - 1 per ray, summed)
  double fieldYears = 0;  // found: the fitted field's years over the same stretches
  // The field's rings from the knot's centre to its edge, in the photo count's units.
  float fieldCount() const {
    return photoRings > 0 ? static_cast<float>(count.rings * fieldYears / photoRings) : 0.0f;
  }
};

struct KnotRingAges {
  int knot = 0;
  std::vector<KnotRingAgeFace> faces;  // one per outline of this knot
  bool counted = false;                // on at least one face
  bool agree = false;                  // the counts and the field's years agree (within their uncertainty)
  std::string note;                    // what they say, in a woodworker's words
};

// One entry per knot with an outline, in the knots' order. `knots`: the fitted ones.
std::vector<KnotRingAges> compareKnotRings(const std::array<Image, 6>& photos, const Block& block,
                                           const GrowthField& stem, const BlockKnots& knots,
                                           const std::vector<KnotOutline>& outlines,
                                           const KnotRingCountOptions& options = {});

}  // namespace kerf
