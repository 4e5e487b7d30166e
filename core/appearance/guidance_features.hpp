#pragma once
// Guidance features of the photo-true appearance (issue 17): what the fitted growth field says about every
// point of a surface, so that a photo pixel and a surface point with the same features show the same
// wood. Image analogies (Hertzmann et al. 2001, Sec. 3) call these the "A" and "B" images: the photos'
// features (evaluated on the faces, at the photos' pixel grid) and the target surface's, from the same
// field, so that the photos' colours ("A'") can be carried to the target ("B'").
//
// Per point p with surface normal n:
//   ring phase     yearPhase(G(p)) as cos/sin(2 pi phase): where in its year the wood was laid down
//                  (earlywood .. latewood), continuous across the ring boundary
//   sawing angles  |n . fibre| (1 = end grain) and |n . grad G| / |grad G| (1 = flat-sawn, tangent to the
//                  rings; 0 = quarter-sawn, across them)
//   ring density   log |grad G| (rings per mm): how wide a ring is
//   sapwood        the heart-to-sapwood blend of the model (color.sapwood_start / _transition)
//   year           G itself (weight 0 by default: the photos rarely cover the same years as a cut)
//   ring angle     the ring bands' direction in the surface relative to the grain direction below
//                  (doubled, scaled by how steeply the rings cross the surface): bands along the fibre
//                  (quarter-sawn stripes) or across it (flat-sawn arches)
//   knot           how much the point is knot wood: the model's knot darkness (Larsson et al. 2022 Sec.
//                  4.3; 0 in clear wood, 1 inside a knot, soft at its edge), so that a knot on a surface is
//                  made of the photos' knot pixels and clear wood never of them. The knot's own rings are
//                  already in the ring phase (the year is the knots' merged field, Mokume Eq. 7). Zero on
//                  every photo of a block without knots, and then not packed (no cost).
// and, to orient patches, the grain direction in the surface's image (radians, x right, y down),
// averaged over about a millimetre: the fibre projected onto the surface on side grain (pores and fibre
// streaks run along it), the in-plane ring tangent on end grain (where the projection vanishes), blended
// by the projection's squared length, and turned so that the in-plane growth gradient points to its
// left-hand normal (-sin, cos): the angle is defined modulo 2 pi, so a patch is never turned upside down
// across the rings (late wood before early wood).
#include <cstdint>
#include <vector>

#include "appearance/surface_grid.hpp"
#include "util/progress.hpp"

namespace kerf {

class WoodModel;

// How much each feature counts in the patch distance (they are stored multiplied by these).
struct GuidanceWeights {
  float phase = 2.0f;
  float sawing = 4.0f;
  float density = 0.3f;
  float sapwood = 0.5f;
  float year = 0.0f;  // per year
  float ringAngle = 2.0f;
  float knot = 10.0f;
};

// cos, sin (phase), end grain, flat-sawn, density, sapwood, year, ring bands against grain (cos, sin), knot
inline constexpr int kGuidanceChannels = 10;
inline constexpr int kKnotChannel = 9;

struct SurfaceGuidance {
  int width = 0, height = 0;
  std::vector<float> features;       // kGuidanceChannels per pixel, row-major, already weighted
  std::vector<float> grainAngle;     // radians, per pixel
  std::vector<std::uint8_t> inside;  // 1 where the point lies in the block
  const float* at(int x, int y) const {
    return &features[(static_cast<std::size_t>(y) * width + x) * kGuidanceChannels];
  }
};

// The features at every pixel of `grid` (rows in parallel; cancellable).
SurfaceGuidance computeGuidance(const WoodModel& model, const SurfaceGrid& grid,
                                const GuidanceWeights& weights, const Progress& progress = {});

// Half the resolution (2 x 2 pixels averaged; the angle through its unit vector): the next pyramid level.
SurfaceGuidance halveGuidance(const SurfaceGuidance& guidance);

}  // namespace kerf
