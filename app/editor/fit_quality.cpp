#include "fit_quality.hpp"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("kerf::FitQuality", text);
}

int percentOfRing(double lossRings) {
  return std::isfinite(lossRings) ? std::max(1, static_cast<int>(std::lround(100 * lossRings))) : 100;
}

}  // namespace

FitGrade gradeFit(double lossRings) {
  if (!(lossRings < 0.2)) return FitGrade::Poor;  // NaN included
  if (lossRings < 0.03) return FitGrade::Close;
  if (lossRings < 0.1) return FitGrade::Good;
  return FitGrade::Rough;
}

QString summarizeFit(double lossRings, bool pithSideAmbiguous, std::optional<FitSureness> sure) {
  static const char* const grades[] = {"close", "good", "rough", "poor"};
  QString text = tr("Fit: %1, rings off by %2 % of a ring width")
                     .arg(tr(grades[static_cast<int>(gradeFit(lossRings))]))
                     .arg(percentOfRing(lossRings));
  if (pithSideAmbiguous) text += tr("; pith side unsure");
  if (sure)
    text +=
        tr("; inside the block ±%1 mm").arg(double(sure->medianMm), 0, 'f', sure->medianMm < 9.95f ? 1 : 0);
  return text;
}

QString explainFit(double lossRings, bool pithSideAmbiguous, std::optional<FitSureness> sure) {
  QString text = tr("On average the fitted rings lie %1 % of a ring's width from the ring lines on the faces "
                    "(iso-contour loss %2 ring spacings).")
                     .arg(percentOfRing(lossRings))
                     .arg(lossRings, 0, 'f', 3);
  switch (gradeFit(lossRings)) {
    case FitGrade::Close:
    case FitGrade::Good:
      text += tr(" Cuts through the block can be trusted to show the rings where they are.");
      break;
    case FitGrade::Rough:
      text +=
          tr(" Look at the yellow and red ring lines (Rings ▸ Show Fit Residuals): a wrong or broken "
             "trace pulls the fit; correct it and fit again.");
      break;
    case FitGrade::Poor:
      text +=
          tr(" The field does not follow the rings: correct the red ring lines (Rings ▸ Show Fit "
             "Residuals), or trace a few rings by hand, and fit again.");
      break;
  }
  if (pithSideAmbiguous)
    text +=
        tr(" The rings fit as well with the pith on the other side of the block: Rings ▸ Use Other Pith "
           "Candidate shows it.");
  if (sure)
    text += tr(" Inside the block, a ring lies within ±%1 mm of where the fit puts it at half the places "
               "(1 sigma, from refits on resampled ring lines), and within ±%2 mm at nine in ten: the cut "
               "shows where (green sure, red unsure; U toggles it).")
                .arg(double(sure->medianMm), 0, 'f', 2)
                .arg(double(sure->p90Mm), 0, 'f', 2);
  else
    text += tr(" How sure the fit is inside the block is estimated in the background after each fit.");
  return text;
}

}  // namespace kerf
