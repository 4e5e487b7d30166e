// RingsController: how sure the fit is (fit/ring_uncertainty_fit.hpp; issue 18 item 4), estimated in the
// background after a fit and kept in the document while its field is the fit's.
#include "document.hpp"
#include "field/ring_uncertainty.hpp"
#include "fit_job.hpp"
#include "job_runner.hpp"
#include "rings_controller.hpp"

namespace kerf {

bool RingsController::isEstimatingUncertainty() const {
  return uncertaintyJob_ && jobs_->isRunning(uncertaintyJob_);
}

void RingsController::cancelUncertainty() {
  if (isEstimatingUncertainty()) jobs_->cancel(uncertaintyJob_);
  uncertaintyJob_ = 0;
}

void RingsController::estimateUncertainty() {
  cancelUncertainty();
  const std::shared_ptr<const GrowthFitResult> fit = lastFit_;
  if (!fit || !fit->input) return;
  // Already known for this field (e.g. Reconstruct re-ran only the wood on it): nothing to redo.
  const RingUncertainty* known = document_->ringUncertainty();
  if (known && known->field == fieldFingerprint(fit->params, fit->rates, fit->knots)) return;
  const Block block = document_->project().block;
  uncertaintyJob_ = jobs_->start(
      tr("Estimating how sure the fit is"),
      [fit, block](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(
            std::make_shared<const RingUncertainty>(estimateFitUncertainty(*fit, block, progress)));
      },
      [this](const QVariant& result) {
        uncertaintyJob_ = 0;
        const auto sure = result.value<std::shared_ptr<const RingUncertainty>>();
        const Project& project = document_->project();
        // The user may have moved on (another fit, an undo, an edit of the rings' parameters).
        if (!sure ||
            sure->field != fieldFingerprint(project.params, project.effectiveRates(), project.knots)) {
          log("info",
              tr("How sure the fit is: estimated for a field that is no longer the document's; dropped"));
          return;
        }
        document_->setRingUncertainty(*sure);
        log("info",
            tr("How sure the fit is: rings within ±%1 mm inside the block (median, 1 sigma), ±%2 mm at "
               "the 90th percentile; the cut shows where (View ▸ Show How Sure the Rings Are, U)")
                .arg(double(sure->quantile(0.5)), 0, 'f', 2)
                .arg(double(sure->quantile(0.9)), 0, 'f', 2));
        emit fitUncertaintyEstimated();
      },
      {}, false);
}

void RingsController::uncertaintyJobEnded(int id, const QString& message) {
  if (id != uncertaintyJob_) return;
  uncertaintyJob_ = 0;
  if (!message.isEmpty()) log("warning", tr("Could not say how sure the fit is: %1").arg(message));
}

}  // namespace kerf
