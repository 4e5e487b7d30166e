// RingsController: the knots follow their marks (issue 19 item 1). A user's edit of the knot marks on the
// last fit's field refits the knots alone (fit/knot_refit.hpp) in the background; they land as one undo
// step while the marks and the stem field are still those they were fitted to.
#include "annotation_layer.hpp"
#include "document.hpp"
#include "field/ring_uncertainty.hpp"
#include "fit/knot_refit.hpp"
#include "job_runner.hpp"
#include "rings_controller.hpp"

namespace kerf {

bool RingsController::isRefittingKnots() const {
  return knotRefitJob_ && jobs_->isRunning(knotRefitJob_);
}

void RingsController::refitKnots() {
  const std::shared_ptr<const GrowthFitResult> fit = lastFit_;
  const Project& project = document_->project();
  if (!fit || !fit->input) return;  // no fit yet: Fit Growth Field places the knots
  // Only on the field the marks' knots were fitted into (not after Undo of the fit or a field edited by
  // hand): the stem is kept as fitted.
  if (!project.rates ||
      fieldFingerprint(project.params, *project.rates, {}) != fieldFingerprint(fit->params, fit->rates, {})) {
    log("info", tr("Knot marks edited: the field is no longer the last fit's, so Fit Growth Field or "
                   "Reconstruct (Ctrl+R) will place the knots"));
    return;
  }
  if (isRefittingKnots()) jobs_->cancel(knotRefitJob_);
  const std::shared_ptr<const GrowthFieldFitInput> input = fit->input;
  const std::vector<KnotMark> marks = project.annotations.knots;
  const WoodParameters params = project.params;
  const GrowthRates rates = *project.rates;
  const Block block = project.block;
  const std::uint64_t stem = fieldFingerprint(params, rates, {});
  knotRefitJob_ = jobs_->start(
      tr("Fitting the knots to their marks"),
      [input, block, params, rates, marks](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(std::make_shared<const KnotRefit>(
            refitKnotsToMarks(*input, block, params, rates, marks, progress)));
      },
      [this, marks, stem](const QVariant& result) {
        knotRefitJob_ = 0;
        const auto refit = result.value<std::shared_ptr<const KnotRefit>>();
        const Project& now = document_->project();
        // Marks moved again meanwhile (their refit follows), or the field changed: this one is stale.
        if (!refit || now.annotations.knots != marks || !now.rates ||
            fieldFingerprint(now.params, *now.rates, {}) != stem)
          return;
        WoodParameters params = now.params;
        params.knotSmoothStem = refit->kStem;
        document_->applyGrowthField(params, now.rates, tr("Knots Follow Their Marks"), refit->knots);
        annotationLayer_->setKnotOutlines(refit->outlines);
        for (const KnotOutline& o : refit->outlines)
          log(o.found ? "info" : "warning",
              tr("Knot K%1's edge on face %2: %3")
                  .arg(o.knot + 1)
                  .arg(QChar(faceLetter(o.face)))
                  .arg(QString::fromStdString(o.found ? o.note : "not used: " + o.note)));
        for (const BlockKnotFitEntry& e : refit->entries) {
          if (!e.kept) {
            log("warning", tr("Knot K%1: not placed: %2").arg(e.id + 1).arg(QString::fromStdString(e.note)));
            continue;
          }
          if (e.releasedMarks >= e.marks) {
            log("info", tr("Knot K%1: its marks are released; the rings placed it").arg(e.id + 1));
            continue;
          }
          log(e.marksHeld ? "info" : "warning",
              tr("Knot K%1 fitted to its marks: its axis passes %2 mm from the farthest mark%3%4")
                  .arg(e.id + 1)
                  .arg(e.markDistanceMm, 0, 'f', 2)
                  .arg(e.marksHeld ? tr(", within its accuracy") : tr(", OUTSIDE its accuracy"))
                  .arg(e.releasedMarks > 0 ? tr("; %n mark(s) released", "", e.releasedMarks) : QString()));
        }
        log("info", tr("Knots fitted again to their marks in %1 s (Ctrl+Z undoes it)")
                        .arg(refit->seconds, 0, 'f', 1));
        emit knotsRefitted();
      },
      {}, false);
}

void RingsController::knotRefitJobEnded(int id, const QString& message) {
  if (id != knotRefitJob_) return;
  knotRefitJob_ = 0;
  if (!message.isEmpty()) log("warning", tr("Could not fit the knots to their marks: %1").arg(message));
}

}  // namespace kerf
