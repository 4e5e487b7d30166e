#pragma once
// Fitting knots into a fitted block growth field, Mokume Sec. 5.2.4 Eq. 7 (field/block_knots.hpp).
//
// Initialisation (the paper: "manually marking the center points of a knot on the external images ...
// from which we construct the initial knot axis"): the marks of one knot id are lifted to 3D on their
// faces; with two marks the axis runs through both, starting where that line passes closest to the
// pith axis; with one mark (a knot seen on one face only) the axis starts on the pith and runs straight
// out to the mark, perpendicular to the pith. A knot with no usable geometry is skipped with a reason.
//
// Optimisation (the paper: "the same optimization framework ... after replacing G with G_k"): with the
// stem field G fixed (after the distortion stage), Ceres (Levenberg-Marquardt, automatic
// differentiation, soft-L1) moves each knot's origin, direction and growth speed, the shared stem-side
// smoothness knots.k_stem (the paper's s) and a free level per contour, on the iso-contour loss (Eq. 2)
// of the contours that come near a knot. Deterministic (one thread). The marks are constraints (issue 19
// item 1): each holds the axis within its accuracyMm, unless the user released it.
#include <optional>
#include <string>
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "fit/iso_contour_loss.hpp"
#include "rings/annotations.hpp"
#include "rings/knot_outline.hpp"
#include "util/progress.hpp"

namespace kerf {

struct BlockKnotFitOptions {
  int maxIterations = 100;
  // A contour point is near a knot when d_k < nearReach * knots.reach_end * d_s for the initial knot.
  float nearReach = 1.25f;
  // The error reported near a knot counts the points within this many knot radii of its initial axis
  // (the knot's radius is its speed x the distance from the pith): where the knot bends the rings
  // sharply, which the coarse growth-rate grid of the distortion stage cannot follow.
  float lossKnotRadii = 3.0f;
  int minNearPoints = 20;  // fewer near points over all contours: the knot is kept at its initial axis
  // More near points than this for one knot: every n-th is fitted (0: all). The editor's live refit
  // (fit/knot_refit.hpp) uses it; its detected traces carry 3-4 times the points of the contours.
  int maxNearPoints = 0;
  bool fitSmoothness = true;
  // Knots to start from instead of the axes of the marks (matched by id), e.g. those fitted on the
  // undeformed field before the distortion stage.
  std::vector<BlockKnot> start;
  // The knots' edges seen on the photos (rings/knot_outline.hpp, matched by id; issue 19 item 2): the
  // knot's surface, where T_k = G, passes through their points. Together they weigh as much as the
  // contour points fitted near the knot. Without them the contours leave the knot's size free and it
  // comes out far too thin (docs/knots.md, the test bed).
  std::vector<KnotOutline> outlines;
  // Issue 19: a knot whose fitted taper reaches this (its edge stopped growing between the faces; the
  // bound is kMaxKnotTaper) becomes a dead knot (BlockKnot::deathTime) that died where it stopped; a dead
  // knot in `start` has its death fitted. Above kMaxKnotTaper: never.
  float deadTaper = 0.9f;
};

// One knot id's outcome.
struct BlockKnotFitEntry {
  int id = 0;
  int marks = 0;              // marks with this id
  std::vector<FaceId> faces;  // their faces
  bool kept = false;          // a knot was added to the field (fitted, or at its initial axis)
  bool optimized = false;     // Ceres moved it
  std::string note;           // how it was initialised, or why it was skipped / not optimised
  BlockKnot initial, fitted;
  double axisMovedDeg = 0;  // angle between the initial and the fitted direction
  // Issue 19 item 1: the fitted axis's largest distance from the marks that hold it (not released), on
  // each mark's face plane (field/block_knots.hpp knotAxisMarkDistance), and whether it is within each
  // one's accuracy.
  double markDistanceMm = 0;
  bool marksHeld = true;
  int releasedMarks = 0;
  int contours = 0, nearPoints = 0;  // contours and points fitted near the knot
  // Issue 19 item 2: the outlines fitted (faces), their edge points, and how far the fitted knot's
  // surface passes from them (median over the points, mm, measured in the stem's ring spacings x w).
  int outlines = 0, edgePoints = 0;
  double edgeDistanceMm = 0;
  int lossPoints = 0;  // points within lossKnotRadii
  // Iso-contour error of the points within lossKnotRadii (mean |G - contour median|, ring spacings =
  // years): without any knot, with the initial knot, with the fitted one.
  double lossWithout = 0, lossInitial = 0, lossFitted = 0;
};

struct BlockKnotFitResult {
  std::vector<BlockKnot> knots;  // the knots kept, in id order
  float kStem = 1.5f;            // knots.k_stem after the fit (unchanged when it was not fitted)
  bool smoothnessFitted = false;
  std::vector<BlockKnotFitEntry> entries;  // one per knot id, ascending
  int iterations = 0;
  double seconds = 0;
};

// The initial knot of one knot id from its marks (see above), or the reason there is none.
struct InitialKnot {
  std::optional<BlockKnot> knot;
  std::string note;
};
InitialKnot initialKnotFromMarks(const std::vector<KnotMark>& marks, const Block& block, const PithAxis& pith,
                                 float speed);

// The iso-contour error (ring spacings) of the points of `contours` for which near[i] is true, each
// measured from its whole contour's lower median of `values`.
double nearKnotLoss(const IsoContours& contours, const std::vector<double>& values,
                    const std::vector<bool>& near);

// Stage 1 for a sample with knots: the pith axis of the undeformed field (G = distance / ring width)
// refined together with the knots (Mokume Sec. 5.2.4: "the same optimization framework ... after
// replacing G with G_k"), starting from the pith fitted without them. A knot bends the rings over much of
// a small block, which otherwise pulls the pith (on the synthetic test block by 10 degrees).
struct PithAndKnotsFit {
  PithAxis pith;  // origin: the point closest to the block centre
  float tiltDeg = 0, azimuthDeg = 0;
  BlockKnotFitResult knots;
};
PithAndKnotsFit fitPithAndKnots(const IsoContours& contours, const Block& block, const PithAxis& pith,
                                float ringWidthMm, const std::vector<KnotMark>& marks,
                                const KnotSettings& settings, const BlockKnotFitOptions& options = {},
                                const Progress& progress = {});

// The contours without the points where `knots` move G by more than `years`, so that the distortion
// stage (Mokume Eq. 4-6) fits the stem's rings and does not bend the growth rates around a knot.
// Contours left with fewer than minPoints points are dropped.
IsoContours contoursAwayFromKnots(const IsoContours& contours, const GrowthField& stem,
                                  const BlockKnots& knots, double years = 0.05, int minPoints = 8);

BlockKnotFitResult fitBlockKnots(const IsoContours& contours, const Block& block, const GrowthField& stem,
                                 const std::vector<KnotMark>& marks, const KnotSettings& settings,
                                 const BlockKnotFitOptions& options = {}, const Progress& progress = {});

}  // namespace kerf
