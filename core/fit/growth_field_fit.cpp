#include "fit/growth_field_fit.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <glm/geometric.hpp>

#include "field/growth_field.hpp"
#include "fit/distortion_fit.hpp"
#include "fit/iso_contour_loss.hpp"
#include "fit/iso_contours.hpp"
#include "util/error.hpp"
#include "util/resource_usage.hpp"

namespace kerf {

namespace {

// A part [from, to] of a job's progress.
Progress part(const Progress& progress, double from, double to) {
  Progress sub{nullptr, progress.stop};
  if (progress.report)
    sub.report = [report = progress.report, from, to](double f) { report(from + (to - from) * f); };
  return sub;
}

std::string format(const char* fmt, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

void addCandidate(std::vector<std::string>& lines, const char* label, const PithCandidate& c,
                  float ringWidthMm) {
  lines.push_back(
      format("%s: O = (%.3f, %.3f, %.3f) mm, V = (%.5f, %.5f, %.5f) (tilt %.2f deg, azimuth %.2f deg), "
             "distance from the block centre %.1f mm",
             label, c.axis.origin.x, c.axis.origin.y, c.axis.origin.z, c.axis.direction.x, c.axis.direction.y,
             c.axis.direction.z, c.tiltDeg, c.azimuthDeg, glm::length(c.axis.origin)));
  lines.push_back(format(
      "  iso-contour loss: %.4f mm = %.4f ring spacings (mean over faces); authors' form 10*sum/40 = %.6f",
      c.loss.meanOverFaces, ringWidthMm > 0 ? c.loss.meanOverFaces / ringWidthMm : 0.0,
      mokumeLoggedLoss(c.loss)));
}

// Step 2 (Mokume Eq. 4-6): growth rates around the fitted axis, rings moved to whole years, rates scaled
// to a median of 1 and the ring width with them (G unchanged), so growth.ring_width stays the typical ring
// width in mm.
GrowthRates fitRates(const IsoContours& contours, const Block& block, const PithAxis& axis, float width0,
                     const std::array<GrayImage8, 6>& images, WoodParameters& params,
                     GrowthFieldFitReport& report, const Progress& progress) {
  const DistortionFitResult d = fitDistortions(contours, block, axis, width0, {}, progress);
  const GrowthField field(axis, width0, d.rates);
  const Stopwatch placementClock;
  const RingLevelEstimate fitted = estimateRingLevels(
      [&field, width0](glm::vec3 p) { return static_cast<double>(field.evaluate(p)) * width0; }, block,
      images);
  std::vector<double> levels;
  for (float peak : fitted.peaksMm) levels.push_back(peak / width0);
  GrowthRates rates = remapRingsToWholeYears(d.rates, width0, levels);
  std::vector<float> sorted = rates.rates;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const float median = sorted[sorted.size() / 2];
  for (float& r : rates.rates) r /= median;
  params.ringWidth = width0 / median;
  params.ringOffset = 0.0f;
  const GrowthField saved(axis, params.ringWidth, rates);
  const IsoContourLoss finalLoss = isoContourLoss(contours, saved, 1.0);
  const double toRings = fitted.ringWidthMm > 0 ? width0 / fitted.ringWidthMm : 1.0;  // rings per year
  report.distortionsFitted = true;
  report.rateHeights = d.rates.heights;
  report.rateAzimuths = d.rates.azimuths;
  report.rateRadii = d.rates.radii;
  report.distortionIterations = d.iterations;
  report.lossBeforeRings = d.lossBefore.meanOverFaces;
  report.lossAfterRings = d.lossAfter.meanOverFaces * toRings;
  report.ringsAlongFitted = static_cast<int>(fitted.peaksMm.size());
  report.finalLossRings = finalLoss.meanOverFaces;
  report.distortionSeconds = d.seconds;
  report.placementSeconds = placementClock.seconds();
  return rates;
}

}  // namespace

GrowthFieldFitResult fitGrowthFieldToSample(const GrowthFieldFitInput& input, const Block& block,
                                            const WoodParameters& current,
                                            const GrowthFieldFitOptions& options, const Progress& progress) {
  GrowthFieldFitResult out;
  GrowthFieldFitReport& report = out.report;
  const Stopwatch extractClock;
  IsoContours contours;
  for (FaceId face : kAllFaces) {
    const GrayImage8& image = input.rings[faceIndex(face)];
    if (image.empty()) continue;
    const auto pixels = extractIsoContours(image);
    addFaceContours(contours, block, face, {image.width, image.height}, pixels);
    report.contoursPerFace[faceIndex(face)] = static_cast<int>(pixels.size());
  }
  report.extractSeconds = extractClock.seconds();
  if (contours.count() < options.minContours || contours.facesWithContours() < options.minFaces)
    throw InputError(
        format("too few ring contours to fit the growth field: %d on %d faces (at least %d on "
               "two faces are needed); detect rings on sharper photos",
               contours.count(), contours.facesWithContours(), options.minContours));
  progress.throwIfCancelled();

  // Anatomical prior (fit/anatomy_prior.hpp): the fibre direction from the face photos' texture.
  if (std::any_of(input.photos.begin(), input.photos.end(), [](const Image& i) { return !i.empty(); }))
    report.anatomy = estimateFibreDirection(input.photos, block);
  PithFitOptions pithOptions;
  pithOptions.principal = options.principal;
  if (report.anatomy && options.useAnatomy && options.anatomyWeight > 0) {
    pithOptions.anatomy = report.anatomy;
    pithOptions.anatomyWeight = options.anatomyWeight;
    report.anatomyUsed = true;
  }
  report.pith = fitPith(contours, block, pithOptions, part(progress, 0.0, options.pithOnly ? 0.95 : 0.45));
  const PithCandidate& best = report.pith.best;
  if (report.anatomy) report.anatomyAngleDeg = anatomyAngleDeg(*report.anatomy, best.axis.direction);

  const Stopwatch ringClock;
  report.rings = estimateRingLevels(best.axis, block, input.rings);
  report.ringSeconds = ringClock.seconds();

  WoodParameters params = current;
  params.pithOrigin = best.axis.origin;
  params.pithTilt = best.tiltDeg;
  params.pithAzimuth = best.azimuthDeg;
  params.ringWidth = report.rings.ringWidthMm;
  params.ringOffset = report.rings.ringOffset;
  // The axis exactly as the parameters rebuild it.
  const PithAxis axis = PithAxis::fromAngles(params.pithOrigin, params.pithTilt, params.pithAzimuth);
  if (options.pithOnly) {
    report.finalLossRings =
        report.rings.ringWidthMm > 0 ? best.loss.meanOverFaces / report.rings.ringWidthMm : 0;
  } else {
    out.rates = fitRates(contours, block, axis, report.rings.ringWidthMm, input.rings, params, report,
                         part(progress, 0.45, 0.95));
  }
  report.ringWidthMm = params.ringWidth;
  progress.set(1.0);
  validate(params);
  out.params = params;
  return out;
}

std::vector<std::string> formatGrowthFieldFitReport(const GrowthFieldFitReport& r) {
  std::vector<std::string> lines;
  std::string perFace;
  for (FaceId face : kAllFaces) {
    const int n = r.contoursPerFace[faceIndex(face)];
    if (n < 0) continue;
    perFace += format("%s%c %d", perFace.empty() ? "" : ", ", faceLetter(face), n);
  }
  lines.push_back("contours per face: " + perFace);
  if (r.anatomy)
    lines.push_back(
        format("anatomy: fibre direction from the texture of %d face photos F = (%.3f, %.3f, %.3f), "
               "confidence %.3f%s",
               r.anatomy->facesUsed, r.anatomy->fibre.x, r.anatomy->fibre.y, r.anatomy->fibre.z,
               r.anatomy->confidence, r.anatomyUsed ? " (used as a prior)" : " (not used by the fit)"));
  else
    lines.push_back("anatomy: no face photos (X_col.png); the pith is fitted to the contours alone");
  for (const std::string& w : r.pith.warnings) lines.push_back("warning: " + w);
  lines.push_back(format("%d contours, %d points (%d used by the continuous fit), %d grid candidates",
                         r.pith.contours, r.pith.points, r.pith.fitPoints, r.pith.gridCandidates));
  addCandidate(lines, "pith", r.pith.best, r.rings.ringWidthMm);
  if (r.anatomy)
    lines.push_back(
        format("anatomy: the pith axis is %.1f deg from the fibre direction: %s", r.anatomyAngleDeg,
               r.anatomyAngleDeg <= 20.0      ? "agrees"
               : r.anatomy->confidence < 0.1f ? "disagrees, but the fibre estimate is weak"
                                              : "DISAGREES - the contours favour an axis the wood "
                                                "anatomy contradicts"));
  lines.push_back(format("rings: width %.4f mm, phase %.4f (%zu rings found, median spacing %.4f mm)",
                         r.rings.ringWidthMm, r.rings.ringOffset, r.rings.peaksMm.size(),
                         r.rings.medianSpacingMm));
  if (r.pith.flipped) {
    lines.push_back(format("ambiguity (Mokume B.1): %s",
                           r.pith.ambiguous
                               ? "AMBIGUOUS - the mirrored pith explains the rings almost as well"
                               : "the mirrored pith is clearly worse"));
    addCandidate(lines, "  other candidate", *r.pith.flipped, r.rings.ringWidthMm);
  } else {
    lines.push_back("ambiguity (Mokume B.1): none (the mirrored start converged to the same axis)");
  }
  if (r.distortionsFitted) {
    lines.push_back(
        format("distortions (Mokume Eq. 4): %d x %d x %d rates, iso-contour loss %.4f -> %.4f ring "
               "spacings (mean over faces), %d iterations",
               r.rateHeights, r.rateAzimuths, r.rateRadii, r.lossBeforeRings, r.lossAfterRings,
               r.distortionIterations));
    lines.push_back(
        format("rings along the fitted field: %d found, moved to whole years; fitted field: "
               "iso-contour loss %.4f ring spacings, typical ring width %.4f mm",
               r.ringsAlongFitted, r.finalLossRings, r.ringWidthMm));
  } else {
    lines.push_back("distortions (Mokume Eq. 4-6) not fitted (pith only): uniform growth rates");
  }
  lines.push_back(
      format("time: contours %.3f s, grid search %.3f s, refinement %.3f s, rings %.3f s, "
             "distortions %.3f s, ring placement %.3f s",
             r.extractSeconds, r.pith.gridSeconds, r.pith.refineSeconds, r.ringSeconds, r.distortionSeconds,
             r.placementSeconds));
  return lines;
}

}  // namespace kerf
