#include "fit/knot_ring_scale.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rings/annotations.hpp"

namespace kerf {

namespace {

// The model's years (G_k) over each span of `count` (where the photo's first and last dark lines lie on
// that ray), summed: the photo saw (lines - 1) rings over the same spans.
double modelYears(const Block& block, const GrowthField& stem, const BlockKnots& knots, const KnotOutline& o,
                  const KnotRingCount& count) {
  const auto yearsAt = [&](glm::vec2 q) {
    const glm::vec3 p = faceMmToBlock(block, o.face, q);
    const Cylindrical c = stem.axis().toCylindrical(p);
    return knots.merge(p, stem.evaluate(c), c.radius).time;
  };
  double sum = 0;
  for (const KnotRingSpan& span : count.spans) {
    const float cr = std::cos(span.angleRad - o.angleRad) / std::max(o.semiAxesMm.x, 1e-3f);
    const float sr = std::sin(span.angleRad - o.angleRad) / std::max(o.semiAxesMm.y, 1e-3f);
    const glm::vec2 edge =
        glm::vec2(std::cos(span.angleRad), std::sin(span.angleRad)) / std::sqrt(cr * cr + sr * sr);
    sum += yearsAt(o.center + span.lastU * edge) - yearsAt(o.center + span.firstU * edge);
  }
  return sum;
}

}  // namespace

std::vector<KnotRingScaleFit> fitKnotRingScales(const std::array<Image, 6>& photos, const Block& block,
                                                const GrowthField& stem, const KnotSettings& settings,
                                                std::vector<BlockKnot>& knots,
                                                const std::vector<KnotOutline>& outlines,
                                                const KnotRingCountOptions& options) {
  std::vector<KnotRingScaleFit> out;
  for (std::size_t k = 0; k < knots.size(); ++k) {
    KnotRingScaleFit fit;
    fit.knot = knots[k].id;
    fit.ringScale = knots[k].ringScale;
    std::vector<const KnotOutline*> counted;
    for (const KnotOutline& o : outlines) {
      if (o.knot != knots[k].id) continue;
      KnotRingCount count = countKnotRings(photos[faceIndex(o.face)], block, o, options);
      if (count.found) counted.push_back(&o);
      fit.counts.push_back(std::move(count));
    }
    if (fit.counts.empty()) continue;
    std::vector<const KnotRingCount*> found;
    for (const KnotRingCount& c : fit.counts)
      if (c.found) found.push_back(&c);
    if (found.empty()) {
      fit.note = "its own rings are not counted on any photo: Eq. 7's rings kept";
      out.push_back(std::move(fit));
      continue;
    }
    // The model's years over the photo's spans on each counted face, at a scale; and the photo's rings
    // over them.
    const auto modelCounts = [&](float scale) {
      std::vector<BlockKnot> trial = knots;
      trial[k].ringScale = scale;
      const BlockKnots model(trial, settings, stem.ringWidth(), stem.axis().direction);
      std::vector<double> years;
      for (std::size_t f = 0; f < counted.size(); ++f)
        years.push_back(modelYears(block, stem, model, *counted[f], *found[f]));
      return years;
    };
    std::vector<double> photoYears;
    for (const KnotRingCount* c : found) {
      double lines = 0;
      for (const KnotRingSpan& span : c->spans) lines += span.lines - 1;
      photoYears.push_back(lines);
    }
    // In the photo's units (rings from the centre to the edge): its count times model / photo years.
    const auto inRings = [&](const std::vector<double>& years) {
      std::vector<float> out;
      for (std::size_t f = 0; f < years.size(); ++f)
        out.push_back(static_cast<float>(found[f]->rings * years[f] / std::max(photoYears[f], 1e-9)));
      return out;
    };
    float scale = knots[k].ringScale;
    std::vector<double> years = modelCounts(scale);
    fit.modelBefore = inRings(years);
    for (int round = 0; round < 4; ++round) {
      // All faces' spans together: photo rings / model years, the model's being close to proportional to
      // the scale inside the knot.
      double photo = 0, model = 0;
      for (std::size_t f = 0; f < years.size(); ++f) photo += photoYears[f], model += years[f];
      if (!(model > 0)) break;
      scale = std::clamp(static_cast<float>(scale * photo / model), kMinKnotRingScale, kMaxKnotRingScale);
      years = modelCounts(scale);
    }
    const std::vector<float> model = inRings(years);
    const bool measured = std::all_of(model.begin(), model.end(), [](float m) { return m > 0; });
    if (!measured) {
      fit.note =
          "the model has no years over the photo's rings (the knot's outline and axis disagree): "
          "Eq. 7's rings kept";
      out.push_back(std::move(fit));
      continue;
    }
    fit.modelAfter = model;
    fit.fitted = true;
    fit.ringScale = scale;
    knots[k].ringScale = scale;
    out.push_back(std::move(fit));
  }
  return out;
}

}  // namespace kerf
