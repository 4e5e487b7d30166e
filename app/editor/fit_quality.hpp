#pragma once
// The fit's quality in a woodworker's words, for the status bar: how far, on average, the fitted rings
// stray from the ring lines they were fitted to (the iso-contour loss, in ring widths; the residual colours
// of Rings > Show Fit Residuals use the same scale: green within 3 %, yellow about 10 %, red 20 % or more).
#include <QString>

namespace kerf {

enum class FitGrade { Close, Good, Rough, Poor };

FitGrade gradeFit(double lossRings);
// Short, for the status bar: "Fit: good, rings off by 5 % of a ring width".
QString summarizeFit(double lossRings, bool pithSideAmbiguous);
// Longer, for its tooltip: what the number means and what to do about it.
QString explainFit(double lossRings, bool pithSideAmbiguous);

}  // namespace kerf
