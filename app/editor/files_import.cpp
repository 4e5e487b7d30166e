// FilesController: File > Import Photos (the user's own photos of the block's faces;
// photo_import_dialog.hpp).
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

#include "document.hpp"
#include "files_controller.hpp"
#include "job_runner.hpp"
#include "photo_import.hpp"
#include "photo_import_dialog.hpp"

namespace kerf {

void FilesController::connectImport() {
  connect(jobs_, &JobRunner::jobFailed, this, [this](int id, const QString& message) {
    if (id != importJob_) return;
    importJob_ = 0;
    showError(tr("The photos could not be imported: %1").arg(message));
  });
  connect(jobs_, &JobRunner::jobCancelled, this, [this](int id) {
    if (id == importJob_) importJob_ = 0;
  });
}

void FilesController::importPhotos(const QStringList& files) {
  if (importJob_ && jobs_->isRunning(importJob_)) {
    showError(tr("Photos are being imported already; wait for that to finish."));
    return;
  }
  QStringList chosen = files;
  if (chosen.isEmpty()) {
    QSettings settings;
    const QString start =
        settings.value("import/folder", QStandardPaths::writableLocation(QStandardPaths::PicturesLocation))
            .toString();
    chosen = QFileDialog::getOpenFileNames(
        window_, tr("Photos of the block's faces"), start,
        tr("Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.webp);;All files (*)"));
    if (chosen.isEmpty()) return;
    settings.setValue("import/folder", QFileInfo(chosen.front()).absolutePath());
  }
  auto* dialog = new PhotoImportDialog(document_->project().block, document_->photos(), window_);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->addPhotos(chosen);
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    const PhotoImportPlan plan = dialog->plan();  // checked by the dialog's accept()
    importJob_ = startPhotoImport(*jobs_, *document_, plan, [this, plan] {
      importJob_ = 0;
      const glm::vec3 size = plan.block.size();
      log("info", tr("Imported the photos of face %1 into %2 (block %3 × %4 × %5 mm, %6 px/mm)")
                      .arg(plan.faceLetters(), plan.folder)
                      .arg(size.x, 0, 'g', 4)
                      .arg(size.y, 0, 'g', 4)
                      .arg(size.z, 0, 'g', 4)
                      .arg(plan.pxPerMm, 0, 'g', 3));
      emit photosImported();
    });
  });
  dialog->open();
}

}  // namespace kerf
