#pragma once
// The fit's quality in a woodworker's words, for the status bar: how far, on average, the fitted rings
// stray from the ring lines they were fitted to (the iso-contour loss, in ring widths; the residual colours
// of Rings > Show Fit Residuals use the same scale: green within 3 %, yellow about 10 %, red 20 % or more).
#include <QString>
#include <optional>

namespace kerf {

enum class FitGrade { Close, Good, Rough, Poor };

FitGrade gradeFit(double lossRings);
// How sure the fit is inside the block (field/ring_uncertainty.hpp), when estimated: the median and the
// 90th percentile of the 1-sigma ring position over the block, in mm.
struct FitSureness {
  float medianMm = 0, p90Mm = 0;
};

// Short, for the status bar: "Fit: good, rings off by 5 % of a ring width; inside ±0.4 mm".
QString summarizeFit(double lossRings, bool pithSideAmbiguous, std::optional<FitSureness> sure = {});
// Longer, for its tooltip: what the numbers mean and what to do about them.
QString explainFit(double lossRings, bool pithSideAmbiguous, std::optional<FitSureness> sure = {});

}  // namespace kerf
