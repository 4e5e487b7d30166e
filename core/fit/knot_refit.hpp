#pragma once
// The knots of a fitted field fitted again after the user moved, released or re-weighed a knot mark
// (issue 19 item 1: the fit follows the marks). Only the knot stage of fitGrowthFieldToSample runs
// (fit/block_knot_fit.hpp, Mokume Sec. 5.2.4): the stem field stays as fitted, the knots start from the
// marks' axes, so a second or two instead of the whole fit.
#include <vector>

#include "field/block_knots.hpp"
#include "field/growth_rates.hpp"
#include "fit/block_knot_fit.hpp"
#include "fit/growth_field_fit.hpp"
#include "params/parameter_schema.hpp"
#include "rings/annotations.hpp"
#include "util/progress.hpp"

namespace kerf {

struct KnotRefit {
  std::vector<BlockKnot> knots;  // the field's knots now (Project::knots)
  float kStem = 0;               // knots.k_stem after the refit
  std::vector<BlockKnotFitEntry> entries;
  std::vector<KnotOutline> outlines;  // each mark's knot edge on its photo, as the refit used them
  double seconds = 0;
};

// `input` is what the field was fitted from (its held-out faces stay unused), `params` and `rates` the
// fitted stem field. Throws Cancelled on request.
KnotRefit refitKnotsToMarks(const GrowthFieldFitInput& input, const Block& block,
                            const WoodParameters& params, const GrowthRates& rates,
                            const std::vector<KnotMark>& marks, const Progress& progress = {});

}  // namespace kerf
