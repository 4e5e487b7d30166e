#pragma once
// Step 1 of the growth-field fit (Mokume Sec. 5.2.3, Eq. 3): the pith axis O, V of an undeformed field
// (R = 1, so g(p) = distance from p to the axis, in mm) that best explains the ring contours.
//
// Method (see pith_fit.cpp for details):
//  1. Coarse grid search. The axis is written in a frame whose third axis is the principal direction
//     (block +y by default): it crosses the plane through the block centre perpendicular to the
//     principal direction at P = u e1 + v e2 and runs along D = a e1 + b e2 + e3. Directions up to
//     maxTiltDeg from the principal one, crossing points from the block centre out to 330 mm; every
//     candidate is scored with the iso-contour loss (median form, per face, as the authors' code) on
//     a few points per contour.
//  2. Continuous refinement of the best distinct grid candidates with Ceres (Levenberg-Marquardt):
//     parameters (u, v, a, b) and one free level per contour; one residual per contour point,
//     rho(dist(p) - level_c) with a soft-L1 robust loss (L2 near 0, L1-like beyond robustScaleMm),
//     which approximates Eq. 2's absolute deviations while staying smooth. Jacobians are computed by
//     automatic differentiation (ceres::Jet) in parallel over fixed chunks of points, each chunk writing
//     its own rows, so the result does not depend on the thread count or scheduling. Linear solver:
//     dense QR on an evenly subsampled set of contour points (maxFitPoints); the final loss is reported on
//     all points.
//  3. Flip ambiguity (Mokume Appendix B.1): the best axis is mirrored through the plane through the
//     block centre perpendicular to the direction towards the pith, and refined again. When it settles on
//     a different axis whose loss is within ambiguityRatio of the best, the fit is ambiguous and both
//     candidates are reported.
//  4. Optional anatomical prior (fit/anatomy_prior.hpp): with `anatomy` set and anatomyWeight > 0, every
//     candidate is ranked by score = loss * (1 + anatomyWeight * penalty(V)), penalty = confidence *
//     (1 - (V.F)^2) for the fibre direction F seen in the photos (grid, refined candidates and the flip
//     choice alike), and the Ceres refinement gets the matching prior residual sqrt(k) * (V x F) with
//     k = 2 * anatomyWeight * confidence * (the contour cost at the start), i.e. the first-order
//     additive form of the same product.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "field/pith_axis.hpp"
#include "fit/anatomy_prior.hpp"
#include "fit/iso_contour_loss.hpp"
#include "fit/iso_contours.hpp"
#include "geometry/block.hpp"
#include "util/progress.hpp"

namespace kerf {

struct PithFitOptions {
  glm::vec3 principal{0, 1, 0};  // the expected pith direction (block +y: B and D are end grain)
  float maxTiltDeg = 55.0f;      // grid: directions within this angle of `principal`
  float tiltStepDeg = 6.0f;      // grid: direction spacing
  std::vector<float> distancesMm{0, 5, 10, 15, 20, 28, 38, 50, 70, 95, 130, 180, 250, 330};
  int originAngles = 24;         // grid: crossing points per distance
  int gridPointsPerContour = 8;  // points per contour used to score grid candidates
  int refineCandidates = 6;      // distinct grid candidates refined with Ceres
  int maxFitPoints = 3000;       // contour points used by the continuous fit (evenly subsampled)
  double robustScaleMm = 0.3;    // soft-L1 scale
  int maxIterations = 100;
  double ambiguityRatio = 1.15;            // flipped candidate within this factor of the best loss: ambiguous
  std::optional<AnatomyEstimate> anatomy;  // fibre direction from the photos (none: contours only)
  double anatomyWeight = 1.0;              // strength of the anatomical prior (0: report only)
  // A plausible tree (issue 18 item 3): a pith farther than this from the block centre is pulled back by
  // a prior that grows linearly beyond it (0: none). A 40 mm block's rings barely curve, so without it
  // the refinement slides along the loss's flat valley to piths metres away (CN03: 1.37 m, 330 rings).
  double plausibleDistanceMm = 0;
};

struct PithCandidate {
  PithAxis axis;                      // origin: the point of the axis closest to the block centre
  float tiltDeg = 0, azimuthDeg = 0;  // growth.pith_tilt / growth.pith_azimuth of axis.direction
  IsoContourLoss loss;    // with g = distance to the axis (mm), all contour points; normalized is 0
  double solverCost = 0;  // Ceres' final cost
  int iterations = 0;
  double anatomyPenalty = 0;  // confidence * (1 - (V.F)^2); 0 without an anatomy estimate
  double score = 0;           // loss.meanOverFaces * (1 + anatomyWeight * anatomyPenalty): the ranking
};

struct PithFitResult {
  PithCandidate best;
  std::optional<PithCandidate> flipped;  // the mirrored candidate after refinement, when distinct
  bool ambiguous = false;
  int contours = 0, points = 0, fitPoints = 0, gridCandidates = 0;
  double gridSeconds = 0, refineSeconds = 0;
  std::vector<std::string> warnings;  // the data cannot support a reliable fit, etc.
};

// Throws InputError without contours, Cancelled when progress.stop is requested.
PithFitResult fitPith(const IsoContours& contours, const Block& block, const PithFitOptions& options = {},
                      const Progress& progress = {});

// Refines one starting axis (same Ceres problem as fitPith's step 2).
PithCandidate refinePith(const IsoContours& contours, const Block& block, const PithAxis& start,
                         const PithFitOptions& options = {}, const Progress& progress = {});

// growth.pith_tilt / growth.pith_azimuth (degrees) of a direction, with the direction turned to +y.
void pithAngles(glm::vec3 direction, float& tiltDeg, float& azimuthDeg);

// Ring iso-values of the undeformed field around `axis` (Mokume Sec. 5.2.3 / MOKUME_CONVENTIONS D,
// with M replaced by the data): the mean ring-localization grey value as a function of the distance to
// the axis (0.05 mm bins over every face pixel, smoothed over 0.3 mm) is thresholded at its mean; the
// centres of the bright runs are the rings. The ring width is the slope of a line through them (whole
// ring numbers assigned from the median spacing), the offset its phase: ring k lies at distance
// ringWidthMm * (ringOffset + k), i.e. at growth.ring_offset + k years of the undeformed field.
struct RingLevelEstimate {
  float ringWidthMm = 0;
  float ringOffset = 0;        // in [0, 1)
  std::vector<float> peaksMm;  // the ring centres found (distance to the axis)
  float medianSpacingMm = 0;
};
// images[f] may be empty (face skipped). Throws InputError when fewer than two rings are found.
RingLevelEstimate estimateRingLevels(const PithAxis& axis, const Block& block,
                                     const std::array<GrayImage8, 6>& images);
// The same along any field monotone across the rings, given in mm-like units (e.g. G * ring width of a
// fitted, distorted field: then ring k lies at G = ringOffset + k once growth.ring_width = ringWidthMm).
RingLevelEstimate estimateRingLevels(const std::function<double(glm::vec3)>& distanceMm, const Block& block,
                                     const std::array<GrayImage8, 6>& images);

}  // namespace kerf
