#pragma once
// A knot's edge on a face photo, found from the user's knot mark (issue 19 item 2: the knot's real size).
// A knot is branch wood cut across, darker than the stem wood around it (Larsson et al. 2022 Sec. 4.3:
// knots.darkening; in real softwood the branch's heartwood and resin). From the mark, rays run outward in
// every direction (cv::warpPolar); on each, the edge is where the brightness first climbs half-way from
// the knot's to the surrounding wood's and stays there for a millimetre (half the step, the usual edge
// of a blurred step; the knot's own lighter rings are narrower than that). An ellipse is fitted to those
// points with the outliers dropped (cv::fitEllipse, trimmed), then the two brightness levels are measured
// again inside and around that ellipse and the edge is traced once more.
//
// The fit (fit/block_knot_fit.hpp) makes the knot's surface, where its own time equals the stem's
// (Mokume Eq. 7), pass through the edge points: the contours around a knot alone leave its size free
// (docs/knots.md, the test bed).
#include <array>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "geometry/block.hpp"
#include "image/image.hpp"
#include "rings/annotations.hpp"

namespace kerf {

struct KnotOutlineOptions {
  float maxRadiusMm = 20.0f;      // rays this long: knots up to 40 mm across
  int rays = 180;                 // one every 2 degrees
  float coreRadiusMm = 1.0f;      // the knot's first brightness level: within this of the mark
  float holdMm = 1.0f;            // the edge: brighter than the level for this long outward
  float minContrast = 0.03f;      // knot to wood (luminance, 0..1) below this: no knot seen
  float minRayShare = 0.5f;       // fewer rays finding an edge (or agreeing with the ellipse): not found
  float inlierTolerance = 0.15f;  // an edge point farther than this share of the radius from the ellipse
};

struct KnotOutline {
  int knot = 0;
  FaceId face = FaceId::A;
  glm::vec2 seed{0.0f};  // face mm: the mark it was found from
  bool found = false;
  std::string note;                    // why none was found, or how well it was
  glm::vec2 center{0.0f};              // face mm: the ellipse's centre
  glm::vec2 semiAxesMm{0.0f};          // the ellipse's half widths, the larger first
  float angleRad = 0;                  // of the first semi-axis, from the face's x towards its y
  std::vector<glm::vec2> edge;         // face mm: the edge points that agree with the ellipse
  int rays = 0;                        // rays that met an edge (before the outliers were dropped)
  float knotLevel = 0, woodLevel = 0;  // luminance (0..1) inside and around the knot

  float meanDiameterMm() const { return semiAxesMm.x + semiAxesMm.y; }
};

// The outline of the knot at `mark` on `photo` (the whole face, any channel count; empty: not found).
KnotOutline detectKnotOutline(const Image& photo, const Block& block, const KnotMark& mark,
                              const KnotOutlineOptions& options = {});

// One outline per mark, in the marks' order; faces without a photo, and marks whose edge the user ignores
// (KnotMark::ignoreEdge), give outlines not found (the note says why).
std::vector<KnotOutline> detectKnotOutlines(const std::array<Image, 6>& photos, const Block& block,
                                            const std::vector<KnotMark>& marks,
                                            const KnotOutlineOptions& options = {});

}  // namespace kerf
