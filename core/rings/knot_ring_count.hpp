#pragma once
// How many of its own rings a knot shows on a face photo (issue 19 item 2: the knot's own rings, and what
// a woodworker counts to tell a branch's age). A knot cut across shows its branch's annual rings as
// closed curves around its pith, one per year of the branch (Larsson et al. 2022 Sec. 4.1: the knot time
// grows linearly with the distance from the knot's axis within a section, so the rings are evenly spaced
// from the knot's centre to its edge). Counting them gives the years between the branch's start and its
// edge on this face: the stem's age there for a live knot, the branch's life for a dead one.
//
// From the knot's outline (rings/knot_outline.hpp) rays run from its centre to its edge. On each, between
// `inner` and `outer` of the way out, the rings are its dark lines (a softwood knot's latewood; the dark
// band of a smoother profile): minima deeper than the photo's noise by a margin and at least minLinePx
// apart, counted and divided by the share of the radius looked at (the ray's length cancels, so an
// oblique cut's ellipse counts as a round knot does; the rings may be unevenly wide, as a real branch's
// are). The count is the mean over the rays; rays are grouped in sectors, and the spread of the sectors'
// means is its uncertainty. Rings closer than minPxPerRing are not counted (too close to count reliably, or
// the photo's aliasing); too few, or sectors that disagree, say that no rings are seen.
#include <string>
#include <vector>

#include "geometry/block.hpp"
#include "image/image.hpp"
#include "rings/knot_outline.hpp"

namespace kerf {

struct KnotRingCountOptions {
  float inner = 0.15f, outer = 0.85f;  // the share of each ray used (the centre and the edge left out)
  int rays = 180;
  int neighbourRays = 10;  // each ray's median with this many on either side (rings line up, pores do not)
  int sectors = 8;         // groups of rays for the uncertainty
  float minRings = 2.5f;   // fewer: no rings seen
  float minLinePx = 3.0f;  // dark lines closer than this (photo px) are one
  // Rings closer than this on the shortest ray are not counted: thin lines this close come out shallow
  // and some are missed (a synthetic knot of 14 rings 5 px apart counted 12.4 +- 0.5).
  float minPxPerRing = 6.0f;
  float smoothPx = 0.6f;           // the rays' smoothing (Gaussian sigma, photo pixels)
  float minDepth = 0.015f;         // a dark line is at least this much darker (luminance 0..1) ...
  float depthOverNoise = 4.0f;     // ... and this many times the photo's noise left after the smoothing
  float maxRelativeSigma = 0.12f;  // the sectors' counts must agree to this share of the count
};

// One ray's dark lines: `lines` of them, the first at `firstU`, the last at `lastU` (shares of the way from
// the outline's centre to its edge in the direction `angleRad`, face mm from x towards y).
struct KnotRingSpan {
  float angleRad = 0, firstU = 0, lastU = 0;
  int lines = 0;
};

struct KnotRingCount {
  int knot = 0;
  FaceId face = FaceId::A;
  bool found = false;
  std::string note;                 // why no count, or what was counted
  float rings = 0;                  // the knot's own rings from its centre to its edge
  float sigma = 0;                  // one standard deviation of `rings`
  float lineContrast = 0;           // the dark lines' median depth over the noise
  float pxPerRing = 0;              // the rings' spacing on the photo along the shortest ray
  std::vector<KnotRingSpan> spans;  // the rays with three dark lines or more
};

// The rings of the knot of `outline` (found) on `photo` (its face's photo; any channel count).
KnotRingCount countKnotRings(const Image& photo, const Block& block, const KnotOutline& outline,
                             const KnotRingCountOptions& options = {});

}  // namespace kerf
