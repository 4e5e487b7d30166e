#pragma once
// The whole growth-field fit of a sample, shared by `kerf-cli fit` and the editor's Fit Growth Field job
// (Mokume Sec. 5.2): contours from the ring-localization images (fit/iso_contours.hpp), an optional
// anatomical prior from the face photos (fit/anatomy_prior.hpp), step 1 the pith axis of an undeformed
// field (Sec. 5.2.3, fit/pith_fit.hpp) with the ring width and phase along it, and step 2 the growth rates
// R (Eq. 4-6, fit/distortion_fit.hpp) with the rings moved to whole years.
#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "field/growth_rates.hpp"
#include "fit/anatomy_prior.hpp"
#include "fit/block_knot_fit.hpp"
#include "fit/iso_contours.hpp"
#include "fit/knot_colour_fit.hpp"
#include "fit/knot_ring_ages.hpp"
#include "fit/pith_fit.hpp"
#include "geometry/block.hpp"
#include "geometry/face_set.hpp"
#include "io/image.hpp"
#include "params/parameter_schema.hpp"
#include "rings/annotations.hpp"
#include "util/progress.hpp"
#include "util/report_line.hpp"

namespace kerf {

struct GrowthFieldFitInput {
  std::array<GrayImage8, 6> rings;  // ring-localization images, A..F; empty: the face is skipped
  std::array<Image, 6> photos;      // face photos for the anatomical prior, A..F; empty: none
  // The user's ring traces (rings/annotations.hpp), fitted as contours besides the images' ones;
  // numbered traces pin the rings to their years (learned-inference paper Eq. 5).
  std::vector<RingTrace> traces;
  // False: the images give no contours, only the ring levels and the image term (the editor, where the
  // detected contours became traces the user corrected).
  bool contoursFromImages = true;
  // Knot centres marked on the faces (rings/annotations.hpp); marks sharing an id are one knot, fitted
  // into the field after the distortions (Mokume Sec. 5.2.4, fit/block_knot_fit.hpp).
  std::vector<KnotMark> knotMarks;
  // Faces held out of the fit (leave-one-face-out, fit/held_out_faces.hpp): their ring images, photos,
  // traces and knot marks above are dropped before any stage reads them, and their tints are neutral.
  FaceSet heldOut;
};

// What the editor and the CLI need before they fit a sample: ring contours on two faces at least, since
// one face alone leaves the pith's distance and direction free (the fit would then return a plausible-
// looking field the data never determined).
inline constexpr int kMinFitContours = 4;
inline constexpr int kMinFitFaces = 2;

struct GrowthFieldFitOptions {
  glm::vec3 principal{0, 1, 0};  // the expected pith direction
  bool pithOnly = false;         // step 1 only: no growth rates are fitted
  bool useAnatomy = true;        // the fibre direction of the photos as a prior (always reported)
  double anatomyWeight = 1.0;    // 0: report only
  int minContours = 0;           // fewer contours (or contours on fewer than minFaces faces): InputError
  int minFaces = 0;
  // When the pith side is ambiguous (Mokume B.1), also fit the field around the mirrored candidate.
  bool fitAlternative = true;
  // A pith farther from the block centre is pulled back (fit/pith_fit.hpp; 0: no limit). 500 mm: the
  // radius of a 1 m log; Mokume's 100 cubes lie 15-330 mm from their piths (Fig. 7).
  double plausiblePithDistanceMm = 500;
  // Ring-porous wood with photos: when the side is ambiguous, the pores choose it (fit/pore_band_side.hpp).
  bool pithSideByPores = true;
  // Ring-porous wood with photos and ring lines not numbered by the user: the earlywood starts where the
  // photos' pore band does (fit/pore_band_side.hpp poreBandStart), not at the ring maps' line.
  bool earlywoodByPores = true;
  // Step 3, colour initialisation (fit/colour_fit.hpp), when there are face photos.
  bool fitColours = true;
  // Knots from input.knotMarks (not with pithOnly).
  bool fitKnots = true;
  // Their edges seen on the photos hold their size (rings/knot_outline.hpp, issue 19 item 2); false: the
  // contours alone size them (Mokume Sec. 5.2.4), which leaves the knots far too thin (docs/knots.md).
  bool useKnotOutlines = true;
  // Their own rings counted inside those edges and compared with the field's years (fit/knot_ring_ages.hpp,
  // reported only).
  bool countKnotRings = true;
  // A bootstrap replicate (fit/ring_uncertainty.hpp): the contours are drawn with replacement, whole
  // (the points along one contour do not err independently), with this seed.
  std::optional<std::uint64_t> resampleContoursSeed;
  // Refine the pith from this axis only (no grid search, no mirrored candidate): a replicate starts from
  // the fitted pith, so that it measures the spread around it rather than a different local minimum.
  std::optional<PithAxis> pithStart;
  // Live preview: called (from the fitting thread) with the undeformed field after the pith stage
  // (rates: none) and with the final field.
  std::function<void(const WoodParameters&, const std::optional<GrowthRates>&)> preview;
};

struct GrowthFieldFitReport {
  FaceSet heldOut;                                             // faces the fit did not use
  std::array<int, 6> contoursPerFace{-1, -1, -1, -1, -1, -1};  // -1: no ring image for the face
  PithFitResult pith;                                          // O, V, tilt, azimuth, losses, ambiguity
  RingLevelEstimate rings;                                     // along the undeformed field
  std::optional<AnatomyEstimate> anatomy;                      // with photos
  bool anatomyUsed = false;                                    // as a prior by the pith fit
  double anatomyAngleDeg = 0;                                  // between the pith axis and the fibres
  bool distortionsFitted = false;
  float wobbleRemovedMm = 0;  // the grain wobble (distortion.amplitude) the fit set to 0
  int rateHeights = 0, rateAzimuths = 0, rateRadii = 0, distortionIterations = 0;
  double lossBeforeRings = 0, lossAfterRings = 0;  // distortion fit, mean over faces, ring spacings
  double imageLossBefore = 0, imageLossAfter = 0;  // Eq. 5, mean |M(G) - ARL| (0: no image term)
  int tracesUsed = 0, numberedTraces = 0;          // the user's traces among the contours
  std::optional<double> ageOffset;                 // numbered traces: ring y at G = y - ageOffset
  // The photos' pores by ring phase (fit/pore_band_side.hpp; ring-porous wood only): early minus late
  // under the chosen pith and under the mirrored one; whether they chose the side against the contours.
  std::optional<double> poreBandsChosen, poreBandsMirrored;
  bool pithSideByPores = false;
  // The photos' pore band against the ring lines (fit/pore_band_side.hpp poreBandStart): how far (years)
  // the earlywood was moved so that it starts where the pores do; set when it was measured.
  std::optional<double> earlywoodShift;
  bool earlywoodShifted = false;  // applied (within kMaxEarlywoodShift, rings not numbered by the user)
  std::optional<double> alternativeLossRings;  // the other candidate's field, when fitted
  std::string alternativeNote;                 // why it was not, when it could not be
  bool ringsFromGrayMap = false;               // ring levels from M's peaks (Eq. 6)
  int ringsAlongFitted = 0;                    // rings found along the fitted field
  double finalLossRings = 0;  // the returned field (pith only: the undeformed one), ring spacings
  float ringWidthMm = 0;      // growth.ring_width of the result
  double anatomySeconds = 0;
  bool coloursFitted = false;
  std::array<double, 6> colourL1Before{}, colourL1After{};  // mean |model - photo| per face (0..1)
  double colourSeconds = 0;
  double extractSeconds = 0, ringSeconds = 0, distortionSeconds = 0, placementSeconds = 0;
  // Knots (Mokume Sec. 5.2.4): one entry per marked knot id; k_stem fitted when any knot was optimised.
  std::vector<BlockKnotFitEntry> knots;
  std::vector<KnotOutline> knotOutlines;  // one per knot mark, as found on its photo (issue 19 item 2)
  KnotColourFit knotColour;               // knots.darkening from those outlines (with the colours)
  std::vector<KnotRingAges> knotRings;    // each knot's own rings counted on them, against the field's years
  bool knotOutlinesIgnored = false;       // marks, but GrowthFieldFitOptions::useKnotOutlines was off
  bool knotSmoothnessFitted = false;
  float knotSmoothStem = 0;
  int knotIterations = 0;
  double knotPithMovedDeg = 0, knotPithMovedMm = 0;  // the pith refined with the knots (fitPithAndKnots)
  int contoursAwayFromKnots = 0;                     // what the distortion stage fitted
  double knotSeconds = 0;
};

// A whole field around one pith candidate.
struct GrowthFieldFitAlternative {
  WoodParameters params;
  std::optional<GrowthRates> rates;
  PithCandidate pith;
  double finalLossRings = 0;
  // Knots fitted on this candidate's undeformed field (before the distortions; fit/block_knot_fit.hpp).
  std::vector<BlockKnot> knots;
  float knotSmoothStem = 0;
};

// One contour after the fit: where it is (block mm) and how far its points stray from their own ring.
struct ContourResidual {
  FaceId face = FaceId::A;
  std::vector<glm::vec3> points;
  double residualRings = 0;  // mean |G - median G| over its points, in ring spacings
  std::optional<int> year;   // numbered trace
  bool fromTrace = false;    // a user's trace (else a contour of a ring-localization image)
};

struct GrowthFieldFitResult {
  WoodParameters params;  // the input parameters with growth.pith_*, ring_width, ring_offset replaced
  std::optional<GrowthRates> rates;  // none with pithOnly (uniform rates around the fitted axis)
  GrowthFieldFitReport report;
  // The field around the mirrored pith when the fit was ambiguous (options.fitAlternative).
  std::optional<GrowthFieldFitAlternative> alternative;
  std::vector<ContourResidual> contours;  // every contour fitted, with its residual under `params`
  std::vector<BlockKnot> knots;           // the knots of the field (Project::knots)
};

// The contours a fit of `input` fits: the iso-contours of its ring images (held-out faces are the
// caller's business) and its traces; fills the report's contour counts when given one.
IsoContours sampleContours(const GrowthFieldFitInput& input, const Block& block,
                           GrowthFieldFitReport* report = nullptr);

// Throws InputError when there is nothing to fit (see minContours), Cancelled on request.
GrowthFieldFitResult fitGrowthFieldToSample(const GrowthFieldFitInput& input, const Block& block,
                                            const WoodParameters& current,
                                            const GrowthFieldFitOptions& options = {},
                                            const Progress& progress = {});

// The report as log lines (contour counts, O, V, losses, anatomy, ambiguity, timings); the pith fit's
// warnings are lines of Severity::Warning.
std::vector<ReportLine> formatGrowthFieldFitReport(const GrowthFieldFitReport& report);

}  // namespace kerf
