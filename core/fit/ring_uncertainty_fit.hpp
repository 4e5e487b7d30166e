#pragma once
// How sure the growth-field fit is, inside the block (issue 18 item 4). The field is refitted on
// bootstrap replicates of the ring contours: whole contours drawn with replacement, since the points along
// one contour do not err independently. Each replicate starts from the fitted pith (refinement only) and
// fits the growth rates again. At every node of a grid over the block, the ring position of each replicate
// is compared with the fitted one: the RMS of the phase difference (wrapped to half a ring), times the
// local ring spacing, is the 1-sigma uncertainty of where a ring lies, in mm. A bootstrap misses the fit's
// systematic errors, so the spread is scaled by a factor measured on synthetic blocks with a known field
// (kRingUncertaintyCalibration, docs/fitting.md "How sure the fit is").
//
// Not included: the knots (replicates keep the fitted knots), the colours, and the choice of pith side
// (each replicate keeps the fitted side; the mirrored candidate is reported by the fit itself).
#include <cstdint>

#include "field/ring_uncertainty.hpp"
#include "fit/growth_field_fit.hpp"
#include "geometry/block.hpp"
#include "render/wood_model.hpp"
#include "util/progress.hpp"

namespace kerf {

// The bootstrap's spread times this is the 1-sigma band: measured by bench/calibrate_ring_uncertainty on
// 12 synthetic blocks (8 refits each), it makes the band hold the true ring position at 68 % of their
// nodes; left out in turn, each block gets 53-92 % (mean 68 %) from the factor of the other 11
// (docs/fitting.md "How sure the fit is").
inline constexpr float kRingUncertaintyCalibration = 1.88f;

struct RingUncertaintyOptions {
  int replicates = 8;  // refits; the spread's own error is about 1 / sqrt(2 * replicates)
  std::uint64_t seed = 1;
  int nodesAlongLongestSide = 17;  // the grid's resolution (a 40 mm block: a node every 2.5 mm)
  float calibration = kRingUncertaintyCalibration;
};

// The fitted field's uncertainty. `input` and `fitOptions` are those of the fit that gave `fitted` (the
// replicates leave out its colours, knots and mirrored candidate). Throws InputError as the fit does,
// Cancelled on request.
RingUncertainty estimateRingUncertainty(const GrowthFieldFitInput& input, const Block& block,
                                        const GrowthFieldFitResult& fitted,
                                        const GrowthFieldFitOptions& fitOptions,
                                        const RingUncertaintyOptions& options = {},
                                        const Progress& progress = {});

// The fit's ring-position error against a known field, at the uncertainty's nodes: for calibration and
// tests on synthetic blocks. Per node, |phase difference| (wrapped to half a ring) times the true ring
// spacing, in mm, beside the node's sigma.
struct RingErrorsAtNodes {
  std::vector<float> errorMm, sigmaMm;
  // The share of nodes whose error lies within scale x sigma (a calibrated 1-sigma band: about 0.68).
  double coverage(float scale = 1.0f) const;
  // The scale that makes coverage(scale) equal `share` (e.g. 0.68): the q-quantile of error / sigma.
  float scaleForCoverage(double share) const;
};
RingErrorsAtNodes ringErrorsAgainstTruth(const WoodModel& truth, const WoodModel& fitted,
                                         const RingUncertainty& uncertainty);

}  // namespace kerf
