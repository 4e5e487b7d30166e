// MainWindow: the Rings menu (ring detection on the face photos, growth-field fit).
#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <algorithm>
#include <filesystem>

#include "document.hpp"
#include "faces_view.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"
#include "util/error.hpp"

namespace kerf {

void MainWindow::createRingsMenu() {
  QMenu* rings = menuBar()->addMenu(tr("&Rings"));
  rings->setToolTipsVisible(true);
  detectRingsAction_ = rings->addAction(tr("&Detect Rings"), this, &MainWindow::detectRings);
  detectRingsAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
  detectRingsAction_->setToolTip(
      tr("Find the annual rings on every face photo (classical detector) and draw their contours over the "
         "faces; runs in the background (Esc cancels)"));
  fitGrowthAction_ = rings->addAction(tr("&Fit Growth Field"), this, &MainWindow::fitGrowthField);
  fitGrowthAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
  fitGrowthAction_->setToolTip(
      tr("Fit the pith axis, ring width and growth rates to the detected rings (or to the sample "
         "folder's X_arl*.png when none were detected), as kerf-cli fit does; one undo step"));
  rings->addSeparator();
  rings->addAction(showContoursAction_);
  connect(jobs_, &JobRunner::jobFailed, this, &MainWindow::ringJobEnded);
  connect(jobs_, &JobRunner::jobCancelled, this, [this](int id) { ringJobEnded(id, {}); });
}

void MainWindow::clearRingDetection() {
  if (ringJob_ && jobs_->isRunning(ringJob_)) jobs_->cancel(ringJob_);
  ringDetection_.reset();
  facesView_->clearOverlay();
  if (showContoursAction_) showContoursAction_->setEnabled(false);
}

void MainWindow::ringJobEnded(int id, const QString& message) {
  if (id != ringJob_ && id != fitJob_) return;
  const bool fit = id == fitJob_;
  (id == ringJob_ ? ringJob_ : fitJob_) = 0;
  if (message.isEmpty()) {  // cancelled: the runner has logged it
    emit ringJobFailed(tr("cancelled"));
    return;
  }
  lastError_ = message;  // the runner has logged the error; say it where it is seen
  auto* box = new QMessageBox(
      QMessageBox::Warning, tr("Kerf"),
      (fit ? tr("The growth field could not be fitted: %1") : tr("Ring detection failed: %1")).arg(message),
      QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
  emit ringJobFailed(message);
}

void MainWindow::detectRings() {
  if (!hasDocument_ || !document_->hasPhotos()) {
    showError(
        tr("Detect Rings needs photos of the faces: open a sample folder (A_col.png .. F_col.png) or "
           "drop photos on the faces."));
    emit ringJobFailed(lastError_);
    return;
  }
  if (ringJob_ && jobs_->isRunning(ringJob_)) return;  // already under way
  const std::array<QImage, 6> photos = document_->photos();
  const Block block = document_->project().block;
  ringJob_ = jobs_->start(
      tr("Detecting rings"),
      [photos, block](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(
            std::make_shared<const RingDetection>(kerf::detectRings(photos, block, progress)));
      },
      [this](const QVariant& result) {
        ringJob_ = 0;
        ringDetection_ = result.value<std::shared_ptr<const RingDetection>>();
        facesView_->setOverlayPolylines(contourPolylines(*ringDetection_), detectionSizes(*ringDetection_));
        showContoursAction_->setEnabled(true);
        facesView_->setOverlayVisible(showContoursAction_->isChecked());
        QStringList counts;
        double seconds = 0;
        for (FaceId face : kAllFaces) {
          const int i = faceIndex(face);
          if (ringDetection_->arl[i].empty()) continue;
          counts
              << QStringLiteral("%1 %2").arg(QChar(faceLetter(face))).arg(ringDetection_->contours[i].size());
          seconds += ringDetection_->seconds[i];
        }
        logMessage("info", tr("Rings detected on %1 faces: %2 contours (%3), %4 s")
                               .arg(ringDetection_->facesDetected)
                               .arg(ringDetection_->contourCount())
                               .arg(counts.join(", "))
                               .arg(seconds, 0, 'f', 2));
        emit ringsDetected();
      },
      {}, false);
}

void MainWindow::fitGrowthField() {
  if (!hasDocument_) {
    showError(tr("Open a document first."));
    emit ringJobFailed(lastError_);
    return;
  }
  if (fitJob_ && jobs_->isRunning(fitJob_)) return;
  if (ringJob_ && jobs_->isRunning(ringJob_)) {
    showError(tr("Ring detection is still running; fit the growth field when it has finished."));
    emit ringJobFailed(lastError_);
    return;
  }
  // The detected images, else the sample folder's own ring-localization images (read in the job).
  const std::shared_ptr<const RingDetection> detection = ringDetection_;
  std::filesystem::path folder;
  if (!document_->filePath().isEmpty())
    folder = QFileInfo(document_->filePath()).absolutePath().toStdString();
  for (const auto& photo : document_->project().facePhotos)
    if (folder.empty() && !photo.empty()) folder = photo.parent_path();
  if (!detection && folder.empty()) {
    showError(tr("There are no rings to fit: run Rings ▸ Detect Rings on the face photos first."));
    emit ringJobFailed(lastError_);
    return;
  }
  const Block block = document_->project().block;
  const WoodParameters current = document_->project().params;
  const std::array<QImage, 6> photos = document_->photos();  // for the anatomical prior
  logMessage("info", detection ? tr("Fitting the growth field to the detected rings")
                               : tr("Fitting the growth field to the ring images in %1")
                                     .arg(QString::fromStdString(folder.string())));
  fitJob_ = jobs_->start(
      tr("Fitting growth field"),
      [detection, folder, block, current, photos](const Progress& progress,
                                                  const JobRunner::Preview&) -> QVariant {
        std::array<GrayImage8, 6> images;
        if (detection) {
          images = detection->arl;
        } else {
          images = readFolderRingImages(folder);
          if (std::all_of(images.begin(), images.end(), [](const GrayImage8& i) { return i.empty(); }))
            throw InputError("there are no rings to fit: run Rings > Detect Rings first (the folder " +
                             folder.string() + " has no X_arl*.png ring images either)");
        }
        return QVariant::fromValue(std::make_shared<const GrowthFitResult>(
            kerf::fitGrowthField(images, block, current, photos, progress)));
      },
      [this](const QVariant& result) {
        fitJob_ = 0;
        const auto fit = result.value<std::shared_ptr<const GrowthFitResult>>();
        for (const QString& line : fit->report)
          logMessage(line.startsWith("warning") ? "warning" : "info", line);
        try {
          document_->applyGrowthField(fit->params, fit->rates, tr("Fit growth field"));
        } catch (const InputError& e) {
          showError(tr("The fitted growth field is not valid: %1").arg(QString::fromUtf8(e.what())));
          emit ringJobFailed(lastError_);
          return;
        }
        logMessage(fit->ambiguous ? "warning" : "info",
                   tr("Growth field fitted: iso-contour loss %1 ring spacings%2 (Ctrl+Z undoes it)")
                       .arg(fit->lossRings, 0, 'f', 4)
                       .arg(fit->ambiguous ? tr("; the pith side is ambiguous") : QString()));
        emit growthFieldFitted();
      },
      {}, false);
}

}  // namespace kerf
