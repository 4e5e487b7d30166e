#include "fit/knot_refit.hpp"

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
  const IsoContours contours =
      sampleContours(input.heldOut.empty() ? input : withoutHeldOutFaces(input), block);
  const GrowthField stem(params, rates);
  BlockKnotFitOptions options;
  options.maxNearPoints = kLiveRefitNearPoints;
  const BlockKnotFitResult fit =
      fitBlockKnots(contours, block, stem, marks, KnotSettings::fromParameters(params), options, progress);
  out.knots = fit.knots;
  if (fit.smoothnessFitted) out.kStem = fit.kStem;
  out.entries = fit.entries;
  out.seconds = clock.seconds();
  return out;
}

}  // namespace kerf
