#include "fit/knot_refit.hpp"

#include <optional>

#include "field/growth_field.hpp"
#include "fit/held_out_faces.hpp"
#include "util/resource_usage.hpp"

namespace kerf {

namespace {
// Near points fitted per knot: the synthetic test knot is placed to 0.01 mm from 18 000 (its whole fit)
// and the refit must land while the user looks; measured in docs/fitting.md.
constexpr int kLiveRefitNearPoints = 3000;
}  // namespace

KnotRefit refitKnotsToMarks(const GrowthFieldFitInput& input, const Block& block,
                            const WoodParameters& params, const GrowthRates& rates,
                            const std::vector<KnotMark>& marks, const Progress& progress) {
  const Stopwatch clock;
  KnotRefit out;
  out.kStem = params.knotSmoothStem;
  if (marks.empty()) return out;
  // The same contours as the fit, without the faces it held out.
  std::optional<GrowthFieldFitInput> stripped;  // not a copy of the photos unless faces are held out
  if (!input.heldOut.empty()) stripped = withoutHeldOutFaces(input);
  const GrowthFieldFitInput& seen = stripped ? *stripped : input;
  const IsoContours contours = sampleContours(seen, block);
  const GrowthField stem(params, rates);
  BlockKnotFitOptions options;
  options.maxNearPoints = kLiveRefitNearPoints;
  // The knots' edges around the marks as they are now (a moved mark seeds its outline where it lies).
  options.outlines = detectKnotOutlines(seen.photos, block, marks);
  const BlockKnotFitResult fit =
      fitBlockKnots(contours, block, stem, marks, KnotSettings::fromParameters(params), options, progress);
  out.knots = fit.knots;
  if (fit.smoothnessFitted) out.kStem = fit.kStem;
  out.entries = fit.entries;
  out.outlines = options.outlines;
  out.seconds = clock.seconds();
  return out;
}

}  // namespace kerf
