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

QString summarizeFit(double lossRings, bool pithSideAmbiguous) {
  static const char* const grades[] = {"close", "good", "rough", "poor"};
  QString text = tr("Fit: %1, rings off by %2 % of a ring width")
                     .arg(tr(grades[static_cast<int>(gradeFit(lossRings))]))
                     .arg(percentOfRing(lossRings));
  if (pithSideAmbiguous) text += tr("; pith side unsure");
  return text;
}

QString explainFit(double lossRings, bool pithSideAmbiguous) {
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
  return text;
}

}  // namespace kerf
