#include "fit/growth_field_fit.hpp"

#include "fit/knot_colour_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <map>
#include <memory>

#include "field/growth_field.hpp"
#include "fit/colour_fit.hpp"
#include "fit/distortion_fit.hpp"
#include "fit/held_out_faces.hpp"
#include "fit/iso_contour_loss.hpp"
#include "fit/iso_contours.hpp"
#include "fit/pore_band_side.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/resource_usage.hpp"

namespace kerf {

namespace {

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
// With knots (in years of width0): no image term (M would learn the knot's dense rings as extra rings),
// and the rings are placed along the field with the knots merged in.
GrowthRates fitRates(const IsoContours& contours, const Block& block, const PithAxis& axis, float width0,
                     const std::array<GrayImage8, 6>& images, WoodParameters& params,
                     GrowthFieldFitReport& report, const Progress& progress,
                     const BlockKnots* knots = nullptr) {
  const bool anyImage =
      std::any_of(images.begin(), images.end(), [](const GrayImage8& i) { return !i.empty(); });
  const DistortionFitResult d =
      fitDistortions(contours, block, axis, width0, {}, progress, anyImage && !knots ? &images : nullptr);
  const GrowthField field(axis, width0, d.rates);
  const Stopwatch placementClock;
  GrowthRates rates;
  double ringOffset = 0.0, yearsPerRing = 1.0;
  if (contours.numberedContours() > 0) {
    // Numbered traces (learned-inference paper Eq. 5): ring y must lie at G = y - a for one age offset a.
    // The rates give the shape (free levels: the coarse radial grid cannot follow single years); then
    // every numbered year's median level is moved exactly to y - a, a = median(y - level).
    std::map<int, std::vector<double>> perYear;
    for (int c = 0; c < contours.count(); ++c) {
      if (!contours.year[c]) continue;
      for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i)
        perYear[*contours.year[c]].push_back(field.evaluate(contours.points[i]));
    }
    std::vector<double> levels, targets, offsets;
    for (auto& [year, values] : perYear) {
      levels.push_back(lowerMedian(values));
      offsets.push_back(year - levels.back());
    }
    const double ageOffset = lowerMedian(offsets);
    for (const auto& [year, values] : perYear) targets.push_back(year - ageOffset);
    rates = levels.size() >= 2 ? remapRingLevels(d.rates, width0, levels, targets) : d.rates;
    ringOffset = -ageOffset - std::floor(-ageOffset);
    report.ageOffset = ageOffset;
  } else {
    // Ring iso-values A: the peaks of the grey map M (Eq. 6); the ring profile along the fitted field
    // where M shows fewer than two (e.g. no ring image).
    std::vector<double> levels;
    if (d.grayMap) levels = d.grayMap->peakCentres();
    RingLevelEstimate fitted;
    if (levels.size() >= 2) {
      for (double a : levels) fitted.peaksMm.push_back(static_cast<float>(a * width0));
      std::vector<double> gaps;
      for (std::size_t i = 1; i < levels.size(); ++i) gaps.push_back((levels[i] - levels[i - 1]) * width0);
      fitted.ringWidthMm = static_cast<float>(lowerMedian(gaps));
      report.ringsFromGrayMap = true;
    } else {
      fitted = estimateRingLevels(
          [&field, width0, knots](glm::vec3 p) {
            if (!knots) return static_cast<double>(field.evaluate(p)) * width0;
            const Cylindrical c = field.axis().toCylindrical(p);
            return static_cast<double>(knots->merge(p, field.evaluate(c), c.radius).time) * width0;
          },
          block, images);
      levels.clear();
      for (float peak : fitted.peaksMm) levels.push_back(peak / width0);
    }
    rates = remapRingsToWholeYears(d.rates, width0, levels);
    yearsPerRing = fitted.ringWidthMm > 0 ? fitted.ringWidthMm / width0 : 1.0;
    report.ringsAlongFitted = static_cast<int>(fitted.peaksMm.size());
  }
  // Rates scaled to a median of 1 and the ring width with them (G unchanged).
  std::vector<float> sorted = rates.rates;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const float median = sorted[sorted.size() / 2];
  for (float& r : rates.rates) r /= median;
  params.ringWidth = width0 / median;
  params.ringOffset = static_cast<float>(ringOffset);
  report.distortionsFitted = true;
  report.rateHeights = d.rates.heights;
  report.rateAzimuths = d.rates.azimuths;
  report.rateRadii = d.rates.radii;
  report.distortionIterations = d.iterations;
  report.lossBeforeRings = d.lossBefore.meanOverFaces;
  report.lossAfterRings = d.lossAfter.meanOverFaces / yearsPerRing;
  report.imageLossBefore = d.imageLossBefore;
  report.imageLossAfter = d.imageLossAfter;
  report.finalLossRings =
      isoContourLoss(contours, GrowthField(axis, params.ringWidth, rates), 1.0).meanOverFaces;
  report.distortionSeconds = d.seconds;
  report.placementSeconds = placementClock.seconds();
  return rates;
}

// Without ring images: ring width and phase from the numbered contours along the undeformed field, a
// least-squares line through (year, median distance to the axis).
RingLevelEstimate ringLevelsFromNumberedContours(const IsoContours& contours, const PithAxis& axis) {
  std::vector<double> years, radii;
  for (int c = 0; c < contours.count(); ++c) {
    if (!contours.year[c]) continue;
    std::vector<double> r;
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i)
      r.push_back(axis.toCylindrical(contours.points[i]).radius);
    years.push_back(*contours.year[c]);
    radii.push_back(lowerMedian(r));
  }
  const double n = static_cast<double>(years.size());
  double sy = 0, sr = 0, syy = 0, syr = 0;
  for (std::size_t i = 0; i < years.size(); ++i)
    sy += years[i], sr += radii[i], syy += years[i] * years[i], syr += years[i] * radii[i];
  const double den = n * syy - sy * sy;
  if (years.size() < 2 || den <= 1e-9)
    throw InputError(
        "without ring-localization images the fit needs numbered traces of at least two different "
        "years (number the traces, or detect rings first)");
  const double slope = (n * syr - sy * sr) / den;
  if (!(std::abs(slope) > 1e-3))
    throw InputError("the numbered traces do not get wider apart from the pith: check their year numbers");
  RingLevelEstimate est;
  est.ringWidthMm = static_cast<float>(std::abs(slope));
  // Ring y at distance r0 + slope * y; in Kerf's years that is G = r / width; the phase is G's fraction
  // there.
  const double phase = ((sr - slope * sy) / n) / est.ringWidthMm;
  est.ringOffset = static_cast<float>(phase - std::floor(phase));
  est.medianSpacingMm = est.ringWidthMm;
  return est;
}

}  // namespace

IsoContours sampleContours(const GrowthFieldFitInput& input, const Block& block,
                           GrowthFieldFitReport* report) {
  IsoContours contours;
  for (FaceId face : kAllFaces) {
    const GrayImage8& image = input.rings[faceIndex(face)];
    if (image.empty() || !input.contoursFromImages) continue;
    const auto pixels = extractIsoContours(image);
    addFaceContours(contours, block, face, {image.width, image.height}, pixels);
    if (report) report->contoursPerFace[faceIndex(face)] = static_cast<int>(pixels.size());
  }
  const int imageContours = contours.count();
  addTraceContours(contours, block, input.traces);
  if (report) {
    report->tracesUsed = contours.count() - imageContours;
    report->numberedTraces = contours.numberedContours();
  }
  return contours;
}

GrowthFieldFitResult fitGrowthFieldToSample(const GrowthFieldFitInput& input, const Block& block,
                                            const WoodParameters& current,
                                            const GrowthFieldFitOptions& options, const Progress& progress) {
  // Leave-one-face-out: the held-out faces' inputs are dropped here, before any stage below reads them.
  if (!input.heldOut.empty()) {
    GrowthFieldFitResult out = fitGrowthFieldToSample(
        withoutHeldOutFaces(input), block, withNeutralTints(current, input.heldOut), options, progress);
    out.report.heldOut = input.heldOut;
    return out;
  }
  GrowthFieldFitResult out;
  GrowthFieldFitReport& report = out.report;
  const Stopwatch extractClock;
  IsoContours contours = sampleContours(input, block, &report);
  const int imageContours = contours.count() - report.tracesUsed;
  if (options.resampleContoursSeed) contours = resampledContours(contours, *options.resampleContoursSeed);
  report.extractSeconds = extractClock.seconds();
  if (contours.count() < options.minContours || contours.facesWithContours() < options.minFaces)
    throw InputError(
        format("too few ring contours to fit the growth field: %d on %d faces (at least %d on "
               "two faces are needed); detect rings on sharper photos",
               contours.count(), contours.facesWithContours(), options.minContours));
  progress.throwIfCancelled();

  // Anatomical prior (fit/anatomy_prior.hpp): the fibre direction from the face photos' texture.
  const Stopwatch anatomyClock;
  if (std::any_of(input.photos.begin(), input.photos.end(), [](const Image& i) { return !i.empty(); })) {
    // The prior is optional: photos too small or too plain to show the fibres leave the fit without it
    // (the report then has no "anatomy:" line) instead of refusing a sample whose rings are fine.
    try {
      report.anatomy = estimateFibreDirection(input.photos, block);
    } catch (const InputError&) {
    }
  }
  report.anatomySeconds = anatomyClock.seconds();
  // Issue 19 item 2: each marked knot's edge on its photo, which holds the knot's size in both knot stages.
  if (options.fitKnots && options.useKnotOutlines && !input.knotMarks.empty())
    report.knotOutlines = detectKnotOutlines(input.photos, block, input.knotMarks);
  report.knotOutlinesIgnored = options.fitKnots && !options.useKnotOutlines && !input.knotMarks.empty();
  PithFitOptions pithOptions;
  pithOptions.principal = options.principal;
  if (report.anatomy && options.useAnatomy && options.anatomyWeight > 0) {
    pithOptions.anatomy = report.anatomy;
    pithOptions.anatomyWeight = options.anatomyWeight;
    report.anatomyUsed = true;
  }
  pithOptions.plausibleDistanceMm = options.plausiblePithDistanceMm;
  if (options.pithStart) {
    report.pith.best = refinePith(contours, block, *options.pithStart, pithOptions,
                                  progress.part(0.0, options.pithOnly ? 0.95 : 0.45));
    report.pith.contours = contours.count();
    report.pith.points = static_cast<int>(contours.points.size());
  } else {
    report.pith = fitPith(contours, block, pithOptions, progress.part(0.0, options.pithOnly ? 0.95 : 0.45));
  }
  const bool anyImage =
      std::any_of(input.rings.begin(), input.rings.end(), [](const GrayImage8& i) { return !i.empty(); });

  // Everything after the pith for one pith candidate: ring width and phase along it, then the rates.
  auto fieldAround = [&](const PithCandidate& candidate, GrowthFieldFitReport& r, const Progress& sub,
                         bool preview) {
    const Stopwatch ringClock;
    r.rings = anyImage ? estimateRingLevels(candidate.axis, block, input.rings)
                       : ringLevelsFromNumberedContours(contours, candidate.axis);
    r.ringSeconds = ringClock.seconds();
    GrowthFieldFitAlternative field;
    field.params = current;
    // The fitted rates are the wood's own distortions (Mokume Sec. 5.2.3); the procedural grain wobble
    // (Liu Eq. 1) on top would move every ring off the contours it was fitted to: on CN03 it took
    // eval_gf.py's iso-contour error from 0.027 to 0.042. It stays a design control for wood made from
    // scratch.
    r.wobbleRemovedMm = field.params.distortionAmplitude;
    field.params.distortionAmplitude = 0.0f;
    field.params.pithOrigin = candidate.axis.origin;
    field.params.pithTilt = candidate.tiltDeg;
    field.params.pithAzimuth = candidate.azimuthDeg;
    field.params.ringWidth = r.rings.ringWidthMm;
    field.params.ringOffset = r.rings.ringOffset;
    // The axis exactly as the parameters rebuild it.
    const PithAxis axis =
        PithAxis::fromAngles(field.params.pithOrigin, field.params.pithTilt, field.params.pithAzimuth);
    validate(field.params);  // before the costly rates: a pith far outside the ranges is refused at once
    if (preview && options.preview) options.preview(field.params, std::nullopt);
    if (options.pithOnly) {
      r.finalLossRings = r.rings.ringWidthMm > 0 ? candidate.loss.meanOverFaces / r.rings.ringWidthMm : 0;
    } else if (options.fitKnots && !input.knotMarks.empty()) {
      // Knots first, with the pith, on the undeformed field (Mokume fits them with G replaced by G_k,
      // Sec. 5.2.4); the rates are then fitted to the contours away from them, so that they do not bend
      // around a knot themselves, and the knots are refined on the final field below.
      const KnotSettings settings = KnotSettings::fromParameters(field.params);
      BlockKnotFitOptions knotOptions;
      knotOptions.outlines = report.knotOutlines;
      const PithAndKnotsFit joint =
          fitPithAndKnots(contours, block, axis, r.rings.ringWidthMm, input.knotMarks, settings, knotOptions);
      field.knots = joint.knots.knots;
      field.knotSmoothStem = joint.knots.kStem;
      r.knotPithMovedDeg =
          glm::degrees(std::acos(std::min(1.0f, std::abs(glm::dot(joint.pith.direction, axis.direction)))));
      r.knotPithMovedMm = std::max(axis.toCylindrical(joint.pith.origin).radius,
                                   joint.pith.toCylindrical(axis.origin).radius);
      field.params.pithOrigin = joint.pith.origin;
      field.params.pithTilt = joint.tiltDeg;
      field.params.pithAzimuth = joint.azimuthDeg;
      const PithAxis knotAxis = PithAxis::fromAngles(joint.pith.origin, joint.tiltDeg, joint.azimuthDeg);
      KnotSettings fitted = settings;
      fitted.knotSmoothStem = joint.knots.kStem;
      if (anyImage) {
        // Ring width and phase along the merged field in mm (smin(r, d_k / v_k)): the dense rings of the
        // knot then fall on the same levels as the stem's instead of posing as extra rings.
        // Their times in mm too (a ring width of 1): taper age and death scaled from the fit's years.
        std::vector<BlockKnot> inMm = joint.knots.knots;
        for (BlockKnot& k : inMm) k.taperAge *= r.rings.ringWidthMm, k.deathTime *= r.rings.ringWidthMm;
        const BlockKnots mm(inMm, fitted, 1.0f, knotAxis.direction);
        r.rings = estimateRingLevels(
            [&](glm::vec3 p) {
              const float radius = knotAxis.toCylindrical(p, false).radius;
              return static_cast<double>(mm.merge(p, radius, radius).time);
            },
            block, input.rings);
        field.params.ringWidth = r.rings.ringWidthMm;
        field.params.ringOffset = r.rings.ringOffset;
      }
      validate(field.params);
      const GrowthField undeformed(knotAxis, r.rings.ringWidthMm, GrowthRates::uniform(block, knotAxis));
      const IsoContours away = contoursAwayFromKnots(
          contours, undeformed,
          BlockKnots(joint.knots.knots, fitted, r.rings.ringWidthMm, knotAxis.direction));
      r.contoursAwayFromKnots = away.count();
      const BlockKnots inYears(joint.knots.knots, fitted, r.rings.ringWidthMm, knotAxis.direction);
      field.rates =
          fitRates(away, block, knotAxis, r.rings.ringWidthMm, input.rings, field.params, r, sub, &inYears);
    } else {
      field.rates = fitRates(contours, block, axis, r.rings.ringWidthMm, input.rings, field.params, r, sub);
    }
    r.ringWidthMm = field.params.ringWidth;
    field.finalLossRings = r.finalLossRings;
    field.pith = candidate;
    validate(field.params);
    return field;
  };
  const bool alternative = report.pith.ambiguous && report.pith.flipped && options.fitAlternative;
  // On the heap, so that the pores can swap the two without copying (GCC 12 also misreads such copies of
  // the rates' std::optional as uninitialised).
  std::unique_ptr<GrowthFieldFitAlternative> chosen, mirrored;
  // The mirrored candidate's stages write their own copy of the report, taken before either candidate
  // runs, so that it holds only what its own stages found.
  GrowthFieldFitReport other = report;
  if (!alternative) {
    chosen = std::make_unique<GrowthFieldFitAlternative>(
        fieldAround(report.pith.best, report, progress.part(0.45, 0.95), true));
  } else {
    // Mokume B.1: the mirrored pith explains the rings almost as well; fit it too so the user can pick.
    // The two candidates are fitted side by side (parallelTasks): most of a candidate's time is Ceres'
    // linear algebra on one thread (distortion_fit.cpp), so two candidates keep two cores busy, and the
    // loops inside either use both cores whenever the other is not in one. No result changes.
    // Only the chosen one reports progress and previews, so the bar moves forwards only.
    std::optional<std::string> mirroredError;
    parallelTasks(2, [&](int which) {
      if (which == 0) {
        chosen = std::make_unique<GrowthFieldFitAlternative>(
            fieldAround(report.pith.best, report, progress.part(0.45, 0.95), true));
        return;
      }
      try {
        mirrored = std::make_unique<GrowthFieldFitAlternative>(
            fieldAround(*report.pith.flipped, other, Progress{nullptr, progress.stop}, false));
      } catch (const InputError& e) {
        mirroredError = e.what();
      }
    });
    if (mirroredError)
      report.alternativeNote = "the other candidate cannot be used as a field: " + *mirroredError;
  }
  const bool photos =
      std::any_of(input.photos.begin(), input.photos.end(), [](const Image& i) { return !i.empty(); });
  // Ring-porous wood: the pores open each ring on the pith's side (fit/pore_band_side.hpp). Where the
  // contours cannot tell the mirrored pith from this one, the pores choose.
  if (photos && chosen->rates && isRingPorous(current)) {
    const auto placement = [&](const GrowthFieldFitAlternative& field) {
      return poreBandPlacement(GrowthField(field.params, *field.rates), field.params.ringOffset, block,
                               input.photos)
          .earlyMinusLate;
    };
    const double chosenBands = placement(*chosen);
    const std::optional<double> mirroredBands =
        mirrored && mirrored->rates ? std::optional(placement(*mirrored)) : std::nullopt;
    if (options.pithSideByPores && mirroredBands &&
        chosenBands<-kPoreBandSideMargin&& * mirroredBands> kPoreBandSideMargin) {
      std::swap(chosen, mirrored);
      report = std::move(other);  // the per-candidate stages' report of the mirrored pith
      std::swap(report.pith.best, *report.pith.flipped);
      report.pithSideByPores = true;
      report.poreBandsChosen = mirroredBands;
      report.poreBandsMirrored = chosenBands;
    } else {
      report.poreBandsChosen = chosenBands;
      report.poreBandsMirrored = mirroredBands;
    }
  }
  // Where the earlywood starts: the ring maps' lines run through the pore band (fit/pore_band_side.hpp).
  // Only the phase moves (growth.ring_offset), never the rings' shape; a user's numbered traces mark the
  // boundaries themselves and keep them.
  if (photos && chosen->rates && isRingPorous(current) && report.numberedTraces == 0) {
    const double share = std::clamp((1.0 - current.latewoodFraction) * current.poreZone, 0.1, 0.5);
    report.earlywoodShift = poreBandStart(GrowthField(chosen->params, *chosen->rates),
                                          chosen->params.ringOffset, block, input.photos, share);
    if (options.earlywoodByPores && report.earlywoodShift &&
        std::abs(*report.earlywoodShift) <= kMaxEarlywoodShift) {
      chosen->params.ringOffset += static_cast<float>(*report.earlywoodShift);
      report.earlywoodShifted = true;
    }
  }
  if (mirrored) {
    report.alternativeLossRings = mirrored->finalLossRings;
    out.alternative = std::move(*mirrored);
  }
  if (report.anatomy)
    report.anatomyAngleDeg = anatomyAngleDeg(*report.anatomy, report.pith.best.axis.direction);
  out.params = chosen->params;
  out.rates = chosen->rates;
  // Knots (Mokume Sec. 5.2.4, Eq. 7): merged into the fitted field from the user's knot marks.
  if (options.fitKnots && !input.knotMarks.empty() && out.rates) {
    const GrowthField stem(out.params, *out.rates);
    KnotSettings settings = KnotSettings::fromParameters(out.params);
    BlockKnotFitOptions knotOptions;
    knotOptions.start = chosen->knots;  // from the undeformed field
    knotOptions.outlines = report.knotOutlines;
    if (!chosen->knots.empty()) settings.knotSmoothStem = chosen->knotSmoothStem;
    const BlockKnotFitResult knots = fitBlockKnots(contours, block, stem, input.knotMarks, settings,
                                                   knotOptions, progress.part(0.95, 0.97));
    out.knots = knots.knots;
    if (knots.smoothnessFitted) out.params.knotSmoothStem = knots.kStem;
    report.knots = knots.entries;
    report.knotSmoothnessFitted = knots.smoothnessFitted;
    report.knotSmoothStem = knots.kStem;
    report.knotIterations = knots.iterations;
    report.knotSeconds = knots.seconds;
    // The knots' own rings on the photos against the field's years (issue 19 item 2), reported.
    if (options.countKnotRings && photos && !out.knots.empty() && !report.knotOutlines.empty())
      report.knotRings = compareKnotRings(input.photos, block, stem,
                                          BlockKnots(out.knots, KnotSettings::fromParameters(out.params),
                                                     out.params.ringWidth, stem.axis().direction),
                                          report.knotOutlines);
  }
  // Step 3: the colours of the wood and of each face, given the field (Mokume A.2.3).
  if (options.fitColours && photos && out.rates) {
    const ColourFitResult colours =
        fitColours(block, out.params, *out.rates, input.photos, {}, progress.part(0.97, 0.99));
    out.params = colours.params;
    report.coloursFitted = true;
    report.colourL1Before = colours.l1Before;
    report.colourL1After = colours.l1After;
    report.colourSeconds = colours.seconds;
    // The knots' colour from their outlines (issue 19 item 4): the knot darker by what the photos show.
    if (!out.knots.empty() && !report.knotOutlines.empty()) {
      report.knotColour = fitKnotDarkening(input.photos, block, report.knotOutlines);
      if (report.knotColour.fitted) out.params.knotDarkening = report.knotColour.darkening;
    }
  }
  if (options.preview) options.preview(out.params, out.rates);

  // What is left of every contour: its mean distance from its own ring, in ring spacings.
  const PithAxis finalAxis =
      PithAxis::fromAngles(out.params.pithOrigin, out.params.pithTilt, out.params.pithAzimuth);
  const GrowthField final(out.params, out.rates ? *out.rates : GrowthRates::uniform(block, finalAxis));
  const BlockKnots finalKnots(out.knots, KnotSettings::fromParameters(out.params), out.params.ringWidth,
                              finalAxis.direction);
  out.contours.resize(contours.count());
  parallelRows(contours.count(), [&](int c) {
    ContourResidual& cr = out.contours[c];
    cr.face = contours.face[c];
    cr.year = contours.year[c];
    std::vector<double> g;
    for (int i = contours.begin[c]; i < contours.begin[c + 1]; ++i) {
      cr.points.push_back(contours.points[i]);
      const Cylindrical cyl = finalAxis.toCylindrical(contours.points[i]);
      g.push_back(finalKnots.merge(contours.points[i], final.evaluate(cyl), cyl.radius).time);
    }
    std::vector<double> sorted = g;
    const double median = lowerMedian(sorted);
    double sum = 0;
    for (double v : g) sum += std::abs(v - median);
    cr.residualRings = g.empty() ? 0.0 : sum / static_cast<double>(g.size());  // rings at whole years
    cr.fromTrace = c >= imageContours;
  });
  progress.set(1.0);
  return out;
}

std::vector<ReportLine> formatGrowthFieldFitReport(const GrowthFieldFitReport& r) {
  std::vector<std::size_t> warningLines;  // indices into `lines`
  std::vector<std::string> lines;
  std::string perFace;
  for (FaceId face : kAllFaces) {
    const int n = r.contoursPerFace[faceIndex(face)];
    if (n < 0) continue;
    perFace += format("%s%c %d", perFace.empty() ? "" : ", ", faceLetter(face), n);
  }
  if (!r.heldOut.empty()) lines.push_back(heldOutReportLine(r.heldOut));
  lines.push_back("contours per face: " + (perFace.empty() ? std::string("none from ring images") : perFace));
  if (r.tracesUsed > 0)
    lines.push_back(format("ring traces: %d (%d numbered by year)", r.tracesUsed, r.numberedTraces));
  if (r.anatomy)
    lines.push_back(
        format("anatomy: fibre direction from the texture of %d face photos F = (%.3f, %.3f, %.3f), "
               "confidence %.3f%s",
               r.anatomy->facesUsed, r.anatomy->fibre.x, r.anatomy->fibre.y, r.anatomy->fibre.z,
               r.anatomy->confidence, r.anatomyUsed ? " (used as a prior)" : " (not used by the fit)"));
  else
    lines.push_back("anatomy: no face photos (X_col.png); the pith is fitted to the contours alone");
  for (const std::string& w : r.pith.warnings) {
    warningLines.push_back(lines.size());
    lines.push_back(w);
  }
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
  if (r.poreBandsChosen) {
    const double chosen = *r.poreBandsChosen;
    const bool early = chosen > kPoreBandSideMargin, late = chosen < -kPoreBandSideMargin;
    std::string line = format(
        "pore bands (ring-porous wood opens each ring with its large pores): %s under "
        "this pith (early minus late %+.2f)",
        early  ? "at the start of the rings"
        : late ? "at the END of the rings"
               : "not clear",
        chosen);
    if (!r.pithSideByPores && r.poreBandsMirrored)
      line += format(", under the mirrored pith %+.2f", *r.poreBandsMirrored);
    if (r.pithSideByPores && r.poreBandsMirrored)
      line += format(
          "; the mirrored pith, which the contours alone preferred, puts them at the end (%+.2f), so "
          "this side was chosen",
          *r.poreBandsMirrored);
    if (late && !r.pithSideByPores) {
      warningLines.push_back(lines.size());
      line += ": the pores put the pith on the other side of the block; check the ring contours";
    }
    lines.push_back(line);
  }
  if (r.pith.flipped) {
    lines.push_back(format("ambiguity (Mokume B.1): %s",
                           r.pith.ambiguous
                               ? "AMBIGUOUS - the mirrored pith explains the rings almost as well"
                               : "the mirrored pith is clearly worse"));
    addCandidate(lines, "  other candidate", *r.pith.flipped, r.rings.ringWidthMm);
  } else {
    lines.push_back("ambiguity (Mokume B.1): none (the mirrored start converged to the same axis)");
  }
  if (!r.alternativeNote.empty()) lines.push_back("  " + r.alternativeNote);
  if (r.alternativeLossRings)
    lines.push_back(
        format("  the field around the other candidate was fitted too (iso-contour loss %.4f ring "
               "spacings); it can be chosen instead",
               *r.alternativeLossRings));
  if (r.wobbleRemovedMm > 0)
    lines.push_back(
        format("grain wobble (distortion.amplitude) %.2f mm -> 0: the fitted field holds the wood's own "
               "distortions, and a procedural wobble would move its rings off the photos' (the "
               "slider adds it back for looks)",
               r.wobbleRemovedMm));
  if (r.distortionsFitted) {
    lines.push_back(
        format("distortions (Mokume Eq. 4): %d x %d x %d rates, iso-contour loss %.4f -> %.4f ring "
               "spacings (mean over faces), %d iterations",
               r.rateHeights, r.rateAzimuths, r.rateRadii, r.lossBeforeRings, r.lossAfterRings,
               r.distortionIterations));
    if (r.ageOffset)
      lines.push_back(
          format("numbered traces (learned-inference Eq. 5): ring year y at G = y %+.3f; "
                 "fitted field: iso-contour loss %.4f ring spacings, typical ring width %.4f mm",
                 -*r.ageOffset, r.finalLossRings, r.ringWidthMm));
    if (r.imageLossAfter > 0)
      lines.push_back(format("image loss (Mokume Eq. 5, mean |M(G) - ARL|): %.4f -> %.4f", r.imageLossBefore,
                             r.imageLossAfter));
    if (!r.ageOffset)
      lines.push_back(
          format("rings %s: %d found, moved to whole years; fitted field: "
                 "iso-contour loss %.4f ring spacings, typical ring width %.4f mm",
                 r.ringsFromGrayMap ? "at the peaks of the grey map M (Eq. 6)" : "along the fitted field",
                 r.ringsAlongFitted, r.finalLossRings, r.ringWidthMm));
  } else {
    lines.push_back("distortions (Mokume Eq. 4-6) not fitted (pith only): uniform growth rates");
  }
  if (r.earlywoodShift)
    lines.push_back(format("earlywood: the photos' pore band starts %.2f of a year %s the ring lines; %s",
                           std::abs(*r.earlywoodShift), *r.earlywoodShift < 0 ? "before" : "after",
                           r.earlywoodShifted ? "the rings' phase was moved there (growth.ring_offset)"
                                              : "too far to be the same band: the phase was kept"));
  if (r.coloursFitted) {
    std::string faces;
    for (FaceId f : kAllFaces) {
      const int i = faceIndex(f);
      if (r.colourL1Before[i] <= 0) continue;
      faces += format("%s%c %.3f -> %.3f", faces.empty() ? "" : ", ", faceLetter(f), r.colourL1Before[i],
                      r.colourL1After[i]);
    }
    lines.push_back("colours (Mokume A.2.3), mean |model - photo| per face: " + faces);
  }
  for (const BlockKnotFitEntry& k : r.knots) {
    std::string faces;
    for (FaceId f : k.faces) faces += faceLetter(f);
    if (!k.kept) {
      lines.push_back(format("knot %d (marks on %s): skipped: %s", k.id, faces.c_str(), k.note.c_str()));
      continue;
    }
    const BlockKnot& b = k.fitted;
    lines.push_back(
        format("knot %d (marks on %s, Mokume Sec. 5.2.4): %s; O = (%.2f, %.2f, %.2f) mm, "
               "V = (%.4f, %.4f, %.4f), speed %.3f, axis moved %.2f deg by the fit",
               k.id, faces.c_str(), k.note.c_str(), b.origin.x, b.origin.y, b.origin.z, b.direction.x,
               b.direction.y, b.direction.z, b.speed, k.axisMovedDeg));
    // Issue 19 item 1: how the marks held it.
    if (k.releasedMarks < k.marks) {
      std::string held =
          format("  knot %d's axis passes %.2f mm from its farthest mark%s", k.id, k.markDistanceMm,
                 k.marksHeld ? " (within every mark's accuracy)" : " (OUTSIDE a mark's accuracy)");
      if (k.releasedMarks > 0)
        held += format("; %d mark(s) released, only seeding the knot", k.releasedMarks);
      lines.push_back(held);
    } else {
      lines.push_back(format("  knot %d: its %d mark(s) released, only seeding it: the rings placed the knot",
                             k.id, k.releasedMarks));
    }
    for (const KnotOutline& o : r.knotOutlines)
      if (o.knot == k.id)
        lines.push_back(format("  knot %d's edge on face %c: %s", k.id, faceLetter(o.face),
                               o.found ? o.note.c_str() : ("not used: " + o.note).c_str()));
    if (k.edgePoints > 0)
      lines.push_back(format(
          "  knot %d's surface passes %.2f mm (median) from its %d edge points on %d face(s)%s", k.id,
          k.edgeDistanceMm, k.edgePoints, k.outlines,
          k.outlines >= 2
              ? format("; taper %.3f (speed %.3f at %.1f years from the pith)", b.taper, b.speed, b.taperAge)
                    .c_str()
              : ""));
    for (const KnotRingAges& a : r.knotRings) {
      if (a.knot != k.id) continue;
      for (const KnotRingAgeFace& f : a.faces)
        lines.push_back(format("  knot %d's own rings on face %c: %s", k.id, faceLetter(f.count.face),
                               f.count.note.c_str()));
      lines.push_back(format("  knot %d's own rings: %s", k.id, a.note.c_str()));
    }
    lines.push_back(
        format("  iso-contour error near knot %d (%d points within 3 knot radii; %d points on %d "
               "contours fitted): %.4f without a knot, %.4f initial, %.4f fitted (ring spacings)",
               k.id, k.lossPoints, k.nearPoints, k.contours, k.lossWithout, k.lossInitial, k.lossFitted));
  }
  if (!r.knots.empty() && r.distortionsFitted)
    lines.push_back(
        format("knots: the pith refined together with them on the undeformed field (moved %.2f deg, "
               "%.2f mm); distortions fitted to the %d contours away from them",
               r.knotPithMovedDeg, r.knotPithMovedMm, r.contoursAwayFromKnots));
  if (r.knotOutlinesIgnored)
    lines.push_back(
        "knots: sized by the ring contours alone (their edges on the photos ignored, as asked); such knots "
        "come out too thin (docs/knots.md)");
  if (r.knotColour.fitted)
    lines.push_back(format(
        "knots: darkening (Larsson Sec. 4.3) fitted from %d outline(s): %.3f, %.3f, %.3f "
        "(the wood around them %.3f, %.3f, %.3f minus the knots %.3f, %.3f, %.3f)",
        r.knotColour.outlines, r.knotColour.darkening.x, r.knotColour.darkening.y, r.knotColour.darkening.z,
        r.knotColour.woodColour.x, r.knotColour.woodColour.y, r.knotColour.woodColour.z,
        r.knotColour.knotColour.x, r.knotColour.knotColour.y, r.knotColour.knotColour.z));
  if (r.knotSmoothnessFitted)
    lines.push_back(format("knots: k_stem (Eq. 7's smoothness s) fitted to %.3f, %d iterations, %.3f s",
                           r.knotSmoothStem, r.knotIterations, r.knotSeconds));
  lines.push_back(
      format("time: contours %.3f s, anatomy %.3f s, grid search %.3f s, refinement %.3f s, rings %.3f s, "
             "distortions %.3f s, ring placement %.3f s, colours %.3f s",
             r.extractSeconds, r.anatomySeconds, r.pith.gridSeconds, r.pith.refineSeconds, r.ringSeconds,
             r.distortionSeconds, r.placementSeconds, r.colourSeconds));
  std::vector<ReportLine> out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const bool warning = std::find(warningLines.begin(), warningLines.end(), i) != warningLines.end();
    out.push_back({warning ? Severity::Warning : Severity::Info, std::move(lines[i])});
  }
  return out;
}

}  // namespace kerf
