#include "texture/texture_inference.hpp"

#include <algorithm>
#include <cstdio>
#include <glm/common.hpp>

#include "fit/colour_fit.hpp"
#include "fit/held_out_faces.hpp"
#include "texture/detail_space.hpp"
#include "util/error.hpp"
#include "util/resource_usage.hpp"

namespace kerf {
namespace {

std::string format(const char* fmt, auto... args) {
  const int length = std::snprintf(nullptr, 0, fmt, args...);  // report lines are of any length
  std::string text(static_cast<std::size_t>(std::max(length, 0)) + 1, '\0');
  std::snprintf(text.data(), text.size(), fmt, args...);
  text.pop_back();
  return text;
}

WoodParameters scaledSizes(const WoodParameters& start, const std::array<float, 3>& factors) {
  WoodParameters p = start;
  scaleDetailSize(p, DetailFeature::Fibres, factors[0]);
  scaleDetailSize(p, DetailFeature::Pores, factors[1]);
  scaleDetailSize(p, DetailFeature::Rays, factors[2]);
  return p;
}

// Stage 1: the 3 x 3 x 3 grid over fibre, pore and ray sizes around the start. Besides the best grid
// point, the "main effects" point is tried: each feature's factor chosen by its mean loss over the nine
// grid points that share it. A feature the loss hardly sees (faint rays) then follows the average, not the
// noise of the one best point.
WoodParameters coarseSearch(const TextureObjective& objective, const WoodParameters& start,
                            const std::vector<float>& factors, TextureInferenceResult& result,
                            const Progress& progress) {
  std::vector<WoodParameters> grid;
  std::vector<std::array<float, 3>> chosen;
  for (float fibre : factors)
    for (float pore : factors)
      for (float ray : factors) {
        chosen.push_back({fibre, pore, ray});
        grid.push_back(scaledSizes(start, chosen.back()));
      }
  std::vector<TextureScore> scores = objective.evaluate(grid, progress.part(0.0, 0.95));
  result.evaluations += static_cast<int>(grid.size());
  std::array<float, 3> mainEffects{};
  for (int feature = 0; feature < 3; ++feature) {
    double bestMean = 0;
    for (float factor : factors) {
      double sum = 0;
      int count = 0;
      for (std::size_t i = 0; i < grid.size(); ++i)
        if (chosen[i][feature] == factor) sum += scores[i].loss, ++count;
      if (count > 0 && (factor == factors.front() || sum / count < bestMean))
        bestMean = sum / count, mainEffects[feature] = factor;
    }
  }
  if (std::find(chosen.begin(), chosen.end(), mainEffects) == chosen.end()) {
    chosen.push_back(mainEffects);
    grid.push_back(scaledSizes(start, mainEffects));
    scores.push_back(objective.evaluate({grid.back()}, progress.part(0.95, 1.0))[0]);
    ++result.evaluations;
  }
  // The best grid point against the main-effects point (which is a grid point with three factors).
  const std::size_t mainIndex = std::find(chosen.begin(), chosen.end(), mainEffects) - chosen.begin();
  std::size_t best = 0;
  for (std::size_t i = 1; i < scores.size(); ++i)
    if (scores[i].loss < scores[best].loss) best = i;
  // Prefer the main effects unless the best point is clearly (2 %) better: the grid's minimum is noisy.
  if (scores[mainIndex].loss <= 1.02 * scores[best].loss) best = mainIndex;
  if (scores[best].loss >= result.lossBefore) return start;
  result.coarseFactors = chosen[best];
  result.lossAfterCoarse = scores[best].loss;
  return grid[best];
}

}  // namespace

TextureInferenceResult inferTexture(const Block& block, const WoodParameters& params,
                                    const GrowthRates& rates, const std::array<Image, 6>& photos,
                                    const TextureInferenceOptions& options, const Progress& progress) {
  // Leave-one-face-out: the held-out photos are dropped here, before anything below reads them.
  if (!options.heldOut.empty()) {
    requireFaceLeftToFit(options.heldOut);
    std::array<Image, 6> kept = photos;
    clearFaces(kept, options.heldOut);
    TextureInferenceOptions rest = options;
    rest.heldOut = {};
    TextureInferenceResult result =
        inferTexture(block, withNeutralTints(params, options.heldOut), rates, kept, rest, progress);
    result.heldOut = options.heldOut;
    return result;
  }
  const Stopwatch total;
  validate(params);
  const std::vector<DetailCoordinate> coordinates = detailCoordinates(options.parameters);
  const TextureObjective objective(block, rates, params, photos, options.loss);
  TextureInferenceResult result;
  result.crops = static_cast<int>(objective.layout().crops.size());

  Stopwatch stage;
  result.lossBefore = objective.evaluate({params}, progress.part(0.0, 0.02))[0].loss;
  result.evaluations = 1;
  result.lossAfterCoarse = result.lossBefore;
  WoodParameters current = params;
  if (options.coarseSearch && !options.coarseFactors.empty()) {
    result.coarseSearched = true;
    current = coarseSearch(objective, params, options.coarseFactors, result, progress.part(0.02, 0.2));
    if (options.preview && !(current == params)) options.preview(current);
  }
  result.coarseSeconds = stage.seconds();

  // Stage 2: the compass search over the unit coordinates of every searched parameter.
  stage = Stopwatch();
  const WoodParameters base = current;
  const BatchObjective batch = [&](const std::vector<std::vector<double>>& points) {
    std::vector<WoodParameters> candidates;
    for (const auto& u : points) candidates.push_back(decodeDetail(base, coordinates, u));
    std::vector<double> losses;
    for (const TextureScore& score : objective.evaluate(candidates, Progress{nullptr, progress.stop}))
      losses.push_back(score.loss);
    return losses;
  };
  // The encoding clamps to the slider ranges; the search starts from the clamped point's own loss.
  const std::vector<double> u0 = encodeDetail(current, coordinates);
  const double f0 = batch({u0})[0];
  ++result.evaluations;
  const PatternSearchResult search = patternSearch(
      u0, f0, batch, options.search,
      [&](const std::vector<double>& u, double) {
        if (options.preview) options.preview(decodeDetail(base, coordinates, u));
      },
      progress.part(0.2, 0.85));
  result.evaluations += search.evaluations;
  result.sweeps = search.sweeps;
  result.sweepLosses = search.sweepValues;
  result.sweepEvaluations = search.sweepEvaluations;
  result.lossAfterSearch = result.lossAfterCoarse;
  if (search.value < result.lossAfterCoarse) {
    current = decodeDetail(base, coordinates, search.x);
    result.lossAfterSearch = search.value;
  }
  result.searchSeconds = stage.seconds();

  // Stage 3: the colours for the new detail. Two candidates: the colour fit (fit/colour_fit.hpp) run
  // again, and only the face tints scaled so each face's mean colour matches its photo (the detail often
  // darkens the wood; the full refit may flatten the earlywood/latewood contrast that the pores need).
  // The better one is kept when it improves the loss.
  stage = Stopwatch();
  result.lossAfter = result.lossAfterSearch;
  if (options.refitColours) {
    std::vector<WoodParameters> candidates;
    std::vector<const char*> names;
    try {
      candidates.push_back(fitColours(block, current, rates, photos, {}, progress.part(0.85, 0.88)).params);
      names.push_back("colours refitted");
    } catch (const InputError&) {  // e.g. grey photos: the tints alone
    }
    WoodParameters tinted = current;
    const std::array<glm::vec3, 6> ratios = objective.meanColourRatios(current, progress.part(0.88, 0.89));
    glm::vec3* tints[6] = {&tinted.faceTintA, &tinted.faceTintB, &tinted.faceTintC,
                           &tinted.faceTintD, &tinted.faceTintE, &tinted.faceTintF};
    const ParamSpec* tintSpec = findParameter("faces.tint_a");
    for (int i = 0; i < 6; ++i)
      *tints[i] =
          glm::clamp(*tints[i] * ratios[i], glm::vec3(tintSpec->hardMin), glm::vec3(tintSpec->hardMax));
    candidates.push_back(tinted);
    names.push_back("face tints matched");
    const std::vector<TextureScore> scores = objective.evaluate(candidates, Progress{nullptr, progress.stop});
    result.evaluations += static_cast<int>(candidates.size());
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (scores[i].loss < result.lossAfter) {
        current = candidates[i];
        result.lossAfter = scores[i].loss;
        result.colourStep = names[i];
      }
    if (result.colourStep != "colours kept" && options.preview) options.preview(current);
  }
  result.colourSeconds = stage.seconds();
  result.params = current;
  result.composedPoints = objective.shadingCounts().composed;
  for (int g = 0; g < 5; ++g) result.layerPoints[g] = objective.shadingCounts().layers[g];

  // Per-face report, before and after.
  stage = Stopwatch();
  result.fullFaces = options.fullFaceReport;
  TextureScore before, after;
  if (options.fullFaceReport) {
    const std::vector<TextureScore> scores =
        objective.evaluateFullFaces({params, current}, progress.part(0.9, 1.0));
    before = scores[0], after = scores[1];
  } else {
    const std::vector<TextureScore> scores = objective.evaluate({params, current}, progress.part(0.9, 1.0));
    before = scores[0], after = scores[1];
  }
  for (int i = 0; i < 6; ++i)
    result.faces[i] = {before.faces[i].used, objective.orientations()[i], before.faces[i], after.faces[i]};
  result.reportSeconds = stage.seconds();
  result.seconds = total.seconds();
  progress.set(1.0);
  return result;
}

std::vector<std::string> formatTextureInferenceReport(const TextureInferenceResult& r) {
  std::vector<std::string> lines;
  if (!r.heldOut.empty()) lines.push_back(heldOutReportLine(r.heldOut));
  lines.push_back(format(
      "texture, per face (%s), before -> after: grain direction agreement (1 = the photo's), "
      "contrast (1 = the photo's), ring figure correlation, streak length difference (0 = the photo's), "
      "where in the ring the pores sit (difference, 0 = as in the photo), style distance, mean |render - "
      "photo|",
      r.fullFaces ? "whole faces" : "crops"));
  for (FaceId face : kAllFaces) {
    const FaceTextureReport& f = r.faces[faceIndex(face)];
    if (!f.hasPhoto) continue;
    std::string line = format(
        "  %c  %-26s (%4.1f deg to the pith)  grain %.2f -> %.2f   contrast %.2f -> %.2f   figure %.2f -> "
        "%.2f"
        "   streaks %.2f -> %.2f   pore band %.2f -> %.2f   style %.3f -> %.3f   L1 %.4f -> %.4f",
        faceLetter(face), faceGrainName(f.orientation.grain).c_str(), f.orientation.angleToPithDeg,
        f.before.grain, f.after.grain, f.before.contrast, f.after.contrast, f.before.figure, f.after.figure,
        f.before.streak, f.after.streak, f.before.band, f.after.band, f.before.style, f.after.style,
        f.before.l1, f.after.l1);
    if (r.fullFaces) line += format("   L1 at 1 mm %.4f -> %.4f", f.before.l1Blurred, f.after.l1Blurred);
    lines.push_back(line);
  }
  const std::string coarse =
      r.coarseSearched ? format("%.4f (coarse, sizes x%.2g fibres, x%.2g pores, x%.2g rays)",
                                r.lossAfterCoarse, r.coarseFactors[0], r.coarseFactors[1], r.coarseFactors[2])
                       : std::string("(no coarse grid)");
  lines.push_back(format("loss on %d crops: %.4f -> %s -> %.4f (search, %d sweeps) -> %.4f (%s)", r.crops,
                         r.lossBefore, coarse.c_str(), r.lossAfterSearch, r.sweeps, r.lossAfter,
                         r.colourStep.c_str()));
  lines.push_back(format("time: coarse %.2f s, search %.2f s, colours %.2f s, report %.2f s; %d evaluations",
                         r.coarseSeconds, r.searchSeconds, r.colourSeconds, r.reportSeconds, r.evaluations));
  std::string sweeps = "search, loss (evaluations) after each sweep:";
  for (std::size_t i = 0; i < r.sweepLosses.size(); ++i)
    sweeps += format(" %.4f (%d)", r.sweepLosses[i], r.sweepEvaluations[i]);
  lines.push_back(sweeps);
  lines.push_back(
      format("shaded points (millions): composed %.2f; layers: rings %.2f, latewood %.2f, pores %.2f, "
             "rays %.2f, fibres %.2f",
             r.composedPoints * 1e-6, r.layerPoints[0] * 1e-6, r.layerPoints[1] * 1e-6,
             r.layerPoints[2] * 1e-6, r.layerPoints[3] * 1e-6, r.layerPoints[4] * 1e-6));
  return lines;
}

}  // namespace kerf
