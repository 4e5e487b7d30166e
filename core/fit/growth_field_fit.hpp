#pragma once
// The whole growth-field fit of a sample, shared by `kerf-cli fit` and the editor's Fit Growth Field job
// (Mokume Sec. 5.2): contours from the ring-localization images (fit/iso_contours.hpp), an optional
// anatomical prior from the face photos (fit/anatomy_prior.hpp), step 1 the pith axis of an undeformed
// field (Sec. 5.2.3, fit/pith_fit.hpp) with the ring width and phase along it, and step 2 the growth rates
// R (Eq. 4-6, fit/distortion_fit.hpp) with the rings moved to whole years.
#include <array>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "field/growth_rates.hpp"
#include "fit/anatomy_prior.hpp"
#include "fit/iso_contours.hpp"
#include "fit/pith_fit.hpp"
#include "geometry/block.hpp"
#include "io/image.hpp"
#include "params/parameter_schema.hpp"
#include "util/progress.hpp"

namespace kerf {

struct GrowthFieldFitInput {
  std::array<GrayImage8, 6> rings;  // ring-localization images, A..F; empty: the face is skipped
  std::array<Image, 6> photos;      // face photos for the anatomical prior, A..F; empty: none
};

struct GrowthFieldFitOptions {
  glm::vec3 principal{0, 1, 0};  // the expected pith direction
  bool pithOnly = false;         // step 1 only: no growth rates are fitted
  bool useAnatomy = true;        // the fibre direction of the photos as a prior (always reported)
  double anatomyWeight = 1.0;    // 0: report only
  int minContours = 0;           // fewer contours (or contours on fewer than minFaces faces): InputError
  int minFaces = 0;
};

struct GrowthFieldFitReport {
  std::array<int, 6> contoursPerFace{-1, -1, -1, -1, -1, -1};  // -1: no ring image for the face
  PithFitResult pith;                                          // O, V, tilt, azimuth, losses, ambiguity
  RingLevelEstimate rings;                                     // along the undeformed field
  std::optional<AnatomyEstimate> anatomy;                      // with photos
  bool anatomyUsed = false;                                    // as a prior by the pith fit
  double anatomyAngleDeg = 0;                                  // between the pith axis and the fibres
  bool distortionsFitted = false;
  int rateHeights = 0, rateAzimuths = 0, rateRadii = 0, distortionIterations = 0;
  double lossBeforeRings = 0, lossAfterRings = 0;  // distortion fit, mean over faces, ring spacings
  int ringsAlongFitted = 0;                        // rings found along the fitted field
  double finalLossRings = 0;  // the returned field (pith only: the undeformed one), ring spacings
  float ringWidthMm = 0;      // growth.ring_width of the result
  double extractSeconds = 0, ringSeconds = 0, distortionSeconds = 0, placementSeconds = 0;
};

struct GrowthFieldFitResult {
  WoodParameters params;  // the input parameters with growth.pith_*, ring_width, ring_offset replaced
  std::optional<GrowthRates> rates;  // none with pithOnly (uniform rates around the fitted axis)
  GrowthFieldFitReport report;
};

// Throws InputError when there is nothing to fit (see minContours), Cancelled on request.
GrowthFieldFitResult fitGrowthFieldToSample(const GrowthFieldFitInput& input, const Block& block,
                                            const WoodParameters& current,
                                            const GrowthFieldFitOptions& options = {},
                                            const Progress& progress = {});

// The report as log lines (contour counts, O, V, losses, anatomy, ambiguity, timings). Lines that are
// warnings (from the pith fit) start with "warning: ".
std::vector<std::string> formatGrowthFieldFitReport(const GrowthFieldFitReport& report);

}  // namespace kerf
