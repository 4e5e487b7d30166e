// RingsController: ring detection on the face photos, the growth-field fit and its pith candidates.
#include "rings_controller.hpp"

#include <QAction>
#include <QColor>
#include <QFileInfo>
#include <QPolygonF>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "annotation_layer.hpp"
#include "document.hpp"
#include "faces_controller.hpp"
#include "faces_view.hpp"
#include "job_runner.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"

namespace kerf {

RingsController::RingsController(const EditorContext& context, FacesController* faces, FacesView* facesView,
                                 AnnotationLayer* annotationLayer)
    : EditorController(context), faces_(faces), facesView_(facesView), annotationLayer_(annotationLayer) {
  knotRefitTimer_ = new QTimer(this);
  knotRefitTimer_->setSingleShot(true);
  knotRefitTimer_->setInterval(300);
  connect(knotRefitTimer_, &QTimer::timeout, this, &RingsController::refitKnots);
  // The user's edits (not undo and redo, which must not push a step of their own): an edit of the knot
  // marks refits the knots.
  connect(annotationLayer_, &AnnotationLayer::edited, this,
          [this](const Annotations& after, const QString& text) {
            const bool knotMarksEdited = after.knots != document_->annotations().knots;
            document_->editAnnotations(after, text);
            if (knotMarksEdited) knotRefitTimer_->start();
          });
  connect(document_, &Document::annotationsChanged, this, &RingsController::annotationsChanged);
  // The detection belonged to the photos that were there.
  connect(document_, &Document::photosChanged, this, &RingsController::clearRingDetection);
  connect(jobs_, &JobRunner::jobFailed, this, &RingsController::ringJobEnded);
  connect(jobs_, &JobRunner::jobCancelled, this, [this](int id) { ringJobEnded(id, {}); });
  connect(jobs_, &JobRunner::jobFailed, this, &RingsController::uncertaintyJobEnded);
  connect(jobs_, &JobRunner::jobCancelled, this, [this](int id) { uncertaintyJobEnded(id, {}); });
  connect(jobs_, &JobRunner::jobFailed, this, &RingsController::knotRefitJobEnded);
  connect(jobs_, &JobRunner::jobCancelled, this, [this](int id) { knotRefitJobEnded(id, {}); });
}

void RingsController::setActions(const Actions& actions) {
  actions_ = actions;
  connect(actions_.otherPith, &QAction::triggered, this, &RingsController::useOtherPithCandidate);
  connect(actions_.exportAnnotations, &QAction::triggered, this, [this] { exportAnnotations(); });
}

bool RingsController::isBusy() const {
  return (ringJob_ && jobs_->isRunning(ringJob_)) || isFitting();
}

bool RingsController::isFitting() const {
  return fitJob_ && jobs_->isRunning(fitJob_);
}

void RingsController::fail(const QString& message) {
  showError(message);
  emit ringJobFailed(message);
}

void RingsController::clearRingDetection() {
  if (ringJob_ && jobs_->isRunning(ringJob_)) jobs_->cancel(ringJob_);
  ringDetection_.reset();
  facesView_->clearOverlay();
  if (actions_.showContours) actions_.showContours->setEnabled(!document_->annotations().empty());
}

void RingsController::ringJobEnded(int id, const QString& message) {
  if (id != ringJob_ && id != fitJob_) return;
  const bool fit = id == fitJob_;
  (id == ringJob_ ? ringJob_ : fitJob_) = 0;
  if (message.isEmpty()) {  // cancelled: the runner has logged it
    emit ringJobFailed(tr("cancelled"));
    return;
  }
  // The runner has logged the error; say it where it is seen.
  emit alerted(
      (fit ? tr("The growth field could not be fitted: %1") : tr("Ring detection failed: %1")).arg(message),
      message);
  emit ringJobFailed(message);
}

void RingsController::detectRings() {
  if (!faces_->hasDocument() || !document_->hasPhotos()) {
    fail(
        tr("Detect Rings needs photos of the faces: open a sample folder (A_col.png .. F_col.png) or "
           "drop photos on the faces."));
    return;
  }
  if (ringJob_ && jobs_->isRunning(ringJob_)) return;  // already under way
  std::array<QImage, 6> photos = document_->photos();
  clearFaces(photos, document_->project().heldOutFaces);  // leave-one-face-out: no rings from their photos
  const Block block = document_->project().block;
  ringJob_ = jobs_->start(
      tr("Detecting rings"),
      [photos, block, detector = detector_](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(
            std::make_shared<const RingDetection>(kerf::detectRings(photos, block, detector, progress)));
      },
      [this](const QVariant& result) {
        ringJob_ = 0;
        showRingDetection(result.value<std::shared_ptr<const RingDetection>>());
      },
      {}, false);
}

// A detection that has landed: kept with the window, its contours the document's detected ring traces.
void RingsController::showRingDetection(std::shared_ptr<const RingDetection> detection) {
  ringDetection_ = std::move(detection);
  applyDetectedTraces(*ringDetection_);  // editable traces of the document: one undo step
  actions_.showContours->setEnabled(true);
  facesView_->setOverlayVisible(actions_.showContours->isChecked());
  QStringList counts;
  double seconds = 0;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    if (ringDetection_->arl[i].empty()) continue;
    counts << QStringLiteral("%1 %2").arg(QChar(faceLetter(face))).arg(ringDetection_->contours[i].size());
    seconds += ringDetection_->seconds[i];
  }
  log("info", tr("Rings detected on %1 faces: %2 contours (%3), %4 s")
                  .arg(ringDetection_->facesDetected)
                  .arg(ringDetection_->contourCount())
                  .arg(counts.join(", "))
                  .arg(seconds, 0, 'f', 2));
  emit ringsDetected();
}

void RingsController::fitGrowthField() {
  if (!faces_->hasDocument()) {
    fail(tr("Open a document first."));
    return;
  }
  if (fitJob_ && jobs_->isRunning(fitJob_)) return;
  if (ringJob_ && jobs_->isRunning(ringJob_)) {
    fail(tr("Ring detection is still running; fit the growth field when it has finished."));
    return;
  }
  // The detected images, else the sample folder's own ring-localization images (read in the job); the
  // document's ring traces (detected, corrected, drawn) are the contours when there are any.
  const std::shared_ptr<const RingDetection> detection = ringDetection_;
  const std::vector<RingTrace> traces = document_->annotations().traces;
  const std::vector<KnotMark> knotMarks = document_->annotations().knots;
  std::filesystem::path folder;
  if (!document_->filePath().isEmpty())
    folder = QFileInfo(document_->filePath()).absolutePath().toStdString();
  for (const auto& photo : document_->project().facePhotos)
    if (folder.empty() && !photo.empty()) folder = photo.parent_path();
  if (!detection && folder.empty() && traces.empty()) {
    fail(
        tr("There are no rings to fit: run Rings ▸ Detect Rings on the face photos, or trace rings, first."));
    return;
  }
  const Block block = document_->project().block;
  const WoodParameters current = document_->project().params;
  const std::array<QImage, 6> photos = document_->photos();   // for the anatomical prior and the colours
  const FaceSet heldOut = document_->project().heldOutFaces;  // the fit uses nothing of these faces
  log("info", !traces.empty() ? tr("Fitting the growth field to %1 ring traces").arg(traces.size())
              : detection     ? tr("Fitting the growth field to the detected rings")
                              : tr("Fitting the growth field to the ring images in %1")
                                .arg(QString::fromStdString(folder.string())));
  fitJob_ = jobs_->start(
      tr("Fitting growth field"),
      [detection, folder, block, current, photos, traces, knotMarks, heldOut](
          const Progress& progress, const JobRunner::Preview& preview) -> QVariant {
        std::array<GrayImage8, 6> images;
        if (detection) {
          images = detection->arl;
        } else {
          images = readFolderRingImages(folder);
          if (traces.empty() &&
              std::all_of(images.begin(), images.end(), [](const GrayImage8& i) { return i.empty(); }))
            throw InputError("there are no rings to fit: run Rings > Detect Rings first (the folder " +
                             folder.string() + " has no X_arl*.png ring images either)");
        }
        const GrowthFitPreview live = [&preview](const WoodParameters& params, const GrowthRates& rates) {
          preview(QVariant::fromValue(
              std::make_shared<const std::pair<WoodParameters, GrowthRates>>(params, rates)));
        };
        return QVariant::fromValue(std::make_shared<const GrowthFitResult>(kerf::fitGrowthField(
            images, block, current, photos, progress, traces, live, knotMarks, heldOut)));
      },
      [this](const QVariant& result) {
        fitJob_ = 0;
        if (applyFit(result.value<std::shared_ptr<const GrowthFitResult>>())) estimateUncertainty();
      },
      [this](const QVariant& preview) {
        const auto field = preview.value<std::shared_ptr<const std::pair<WoodParameters, GrowthRates>>>();
        if (field) showFitPreview(field->first, field->second);
      },
      false);
}

// A fit that has landed: applied as one undo step, its residuals drawn over the faces, its quality said.
bool RingsController::applyFit(std::shared_ptr<const GrowthFitResult> fit) {
  for (const ReportLine& line : fit->report)
    log(severityName(line.severity), QString::fromStdString(line.text));
  try {
    document_->applyGrowthField(fit->params, fit->rates, tr("Fit growth field"), fit->knots);
  } catch (const InputError& e) {
    const QString message = tr("The fitted growth field is not valid: %1").arg(QString::fromUtf8(e.what()));
    showError(message);
    faces_->showDocumentModel();  // back from the preview to the document's field
    emit ringJobFailed(message);
    return false;
  }
  lastFit_ = fit;
  annotationLayer_->setKnotOutlines(fit->knotOutlines);
  actions_.otherPith->setEnabled(fit->alternative.has_value());
  showFitResiduals(*fit);
  log(fit->ambiguous ? "warning" : "info",
      tr("Growth field fitted: iso-contour loss %1 ring spacings%2 (Ctrl+Z undoes it)")
          .arg(fit->lossRings, 0, 'f', 4)
          .arg(fit->ambiguous ? (fit->alternative ? tr("; the pith side is ambiguous: Rings ▸ Use "
                                                       "Other Pith Candidate shows the other side")
                                                  : tr("; the pith side is ambiguous"))
                              : QString()));
  emit growthFieldFitted();
  return true;
}

// The field being fitted, shown in the 3D view, the cut and the faces before it is applied.
void RingsController::showFitPreview(const WoodParameters& params, const GrowthRates& rates) {
  std::shared_ptr<const WoodModel> model;
  try {
    model = std::make_shared<const WoodModel>(document_->project().block, params, rates);
  } catch (const InputError&) {
    return;  // e.g. a pith candidate outside the ranges: nothing to preview
  }
  faces_->showPreview(model);
  emit fitPreviewed();
}

// Every fitted contour over the photos, coloured by its residual (ring spacings).
void RingsController::showFitResiduals(const GrowthFitResult& fit) {
  const Block& block = document_->project().block;
  std::array<std::vector<QPolygonF>, 6> lines;
  std::array<std::vector<QColor>, 6> colours;
  std::array<QSize, 6> sizes;
  for (FaceId face : kAllFaces) {
    const glm::vec2 mm = faceSizeMm(block, face);
    sizes[faceIndex(face)] =
        QSize(std::max(1, int(std::lround(mm.x * 10))), std::max(1, int(std::lround(mm.y * 10))));
  }
  for (const FittedContour& c : fit.contours) {
    const int f = faceIndex(c.face);
    const glm::ivec2 size(sizes[f].width(), sizes[f].height());
    QPolygonF line;
    for (const glm::vec2& p : c.pointsMm) {
      const glm::vec2 q = faceMmToImage(block, c.face, p, size);
      line << QPointF(q.x, q.y);
    }
    lines[f].push_back(line);
    // Green (0) -> yellow (0.1 ring) -> red (0.2 ring and more).
    const double t = std::clamp(c.residualRings / 0.2, 0.0, 1.0);
    colours[f].push_back(t < 0.5 ? QColor::fromRgbF(float(2 * t), 0.85f, 0.2f)
                                 : QColor::fromRgbF(1.0f, float(0.85 * (2 - 2 * t)), 0.2f));
  }
  facesView_->setOverlayPolylines(lines, sizes, colours);
  facesView_->setOverlayVisible(actions_.showResiduals->isChecked());
  actions_.showResiduals->setEnabled(true);
}

void RingsController::useOtherPithCandidate() {
  if (!lastFit_ || !lastFit_->alternative) return;
  // On the heap: a local copy made GCC 12 warn of the optional's payload (a false maybe-uninitialized).
  const auto swapped = std::make_shared<GrowthFitResult>(*lastFit_);
  GrowthFitResult::Alternative& other = *swapped->alternative;
  std::swap(swapped->params, other.params);
  std::swap(swapped->rates, other.rates);
  std::swap(swapped->lossRings, other.lossRings);
  std::swap(swapped->knots, other.knots);
  try {
    document_->applyGrowthField(swapped->params, swapped->rates, tr("Use other pith candidate"),
                                swapped->knots);
  } catch (const InputError& e) {
    showError(tr("The other pith candidate is not a valid field: %1").arg(QString::fromUtf8(e.what())));
    return;
  }
  lastFit_ = swapped;
  estimateUncertainty();
  log("info", tr("Using the other pith candidate: iso-contour loss %1 ring spacings (again to switch back)")
                  .arg(lastFit_->lossRings, 0, 'f', 4));
}

}  // namespace kerf
