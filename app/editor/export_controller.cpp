// ExportController: File > Export: face and cut images, volumes and depth stacks (export_dialog.hpp) and
// textured parts (part_export_dialog.hpp), written by the core's runExport (the code of `kerf-cli export`) as
// background jobs with progress and cancel.
#include "export_controller.hpp"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <algorithm>

#include "appearance/photo_true_source.hpp"
#include "document.hpp"
#include "job_runner.hpp"
#include "part_export_dialog.hpp"
#include "render/renderers.hpp"
#include "viewport3d.hpp"

namespace kerf {
namespace {

QString exportFolder() {
  return QSettings()
      .value("export/folder", QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
      .toString();
}

}  // namespace

ExportController::ExportController(const EditorContext& context, RenderSettings settings,
                                   Viewport3D* viewport)
    : EditorController(context), settings_(settings), viewport_(viewport) {
  connect(jobs_, &JobRunner::jobFailed, this, [this](int id, const QString& message) {
    if (!forget(id)) return;
    showError(tr("The export failed: %1").arg(message));
    emit exportFailed(message);
  });
  connect(jobs_, &JobRunner::jobFinished, this, [this](int id) { forget(id); });
  connect(jobs_, &JobRunner::jobCancelled, this, [this](int id) {
    if (forget(id)) emit exportFailed(tr("cancelled"));
  });
}

bool ExportController::forget(int id) {
  const auto it = std::find(exportJobs_.begin(), exportJobs_.end(), id);
  if (it == exportJobs_.end()) return false;
  exportJobs_.erase(it);
  return true;
}

ExportDialog* ExportController::showExportDialog(ExportDialog::Kind kind) {
  auto* dialog = new ExportDialog(kind, document_->project().block, document_->cutPlane().plane(),
                                  exportFolder(), window_);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    QSettings().setValue("export/folder", QFileInfo(dialog->path()).absolutePath());
    startExport(dialog->request());
  });
  dialog->open();  // window-modal, returns at once
  return dialog;
}

PartExportDialog* ExportController::showPartExportDialog() {
  auto* dialog = new PartExportDialog(document_->project().block, exportFolder(), window_);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &PartExportDialog::partChanged, viewport_,
          [this](std::shared_ptr<const Mesh> placed) { viewport_->setPart(std::move(placed)); });
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    QSettings().setValue("export/folder", QFileInfo(dialog->path()).absolutePath());
    startExport(dialog->request());
  });
  dialog->show();  // modeless: the 3D view can be turned while placing the part
  return dialog;
}

int ExportController::startExport(ExportRequest request) {
  const auto model = document_->model();
  if (const RingUncertainty* sure = document_->ringUncertainty()) request.ringUncertainty = *sure;
  request.photoTrue = photoTrueSourceOf(document_->project());  // its photos are read on the job
  const QString path = QString::fromStdString(request.out.string());
  const int id = jobs_->start(
      tr("Exporting %1").arg(QFileInfo(path).fileName()),
      [model, request](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        const ExportSummary summary = runExport(*model, request, progress);
        return QStringList{QString::fromStdString(summary.message), QString::fromStdString(summary.warning)};
      },
      [this, path](const QVariant& done) {
        const QString message = done.toStringList().value(0), warning = done.toStringList().value(1);
        log("info", message);
        if (!warning.isEmpty()) log("warning", warning);
        emit statusShown(message, 6000);
        emit exportFinished(path, message);
      },
      {}, false);
  exportJobs_.push_back(id);
  return id;
}

void ExportController::exportFaces() {
  const QString folder =
      QFileDialog::getExistingDirectory(window_, tr("Export model faces to folder"),
                                        QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
  if (folder.isEmpty()) return;
  const auto model = document_->model();
  const float pxPerMm = settings_.pxPerMm * 2;
  const std::optional<PhotoTrueSource> photoTrue = photoTrueSourceOf(document_->project());
  jobs_->start(
      tr("Exporting faces"),
      [model, folder, pxPerMm, photoTrue](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        const auto images = photoTrue ? makePhotoTrueAppearance(*model, *photoTrue, progress.part(0.0, 0.05))
                                            ->renderFaces(pxPerMm, progress.part(0.05, 1.0))
                                      : kerf::renderFaces(*model, pxPerMm, 2, progress);
        for (FaceId face : kAllFaces) {
          writeImage((QDir(folder).filePath(QString("%1.png").arg(QChar(faceLetter(face))))).toStdString(),
                     images[faceIndex(face)]);
        }
        return folder;
      },
      [this](const QVariant& done) { log("info", tr("Faces written to %1").arg(done.toString())); }, {},
      false);
}

}  // namespace kerf
