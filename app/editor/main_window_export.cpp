// MainWindow: File > Export: face and cut images, volumes and depth stacks (export_dialog.hpp) and textured
// parts (part_export_dialog.hpp), written by the core's runExport (the code of `kerf-cli export`) as
// background jobs with progress and cancel.
#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <algorithm>

#include "document.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"
#include "part_export_dialog.hpp"
#include "viewport3d.hpp"

namespace kerf {
namespace {

QString exportFolder() {
  return QSettings()
      .value("export/folder", QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
      .toString();
}

}  // namespace

void MainWindow::createExportActions(QMenu* exportMenu) {
  const struct {
    ExportDialog::Kind kind;
    QString text, tip;
  } entries[] = {
      {ExportDialog::Kind::FaceImage, tr("&Face Image…"),
       tr("A face at true scale as PNG, 16-bit TIFF or OpenEXR, with the growth field and ring lines as "
          "layers")},
      {ExportDialog::Kind::CutImage, tr("&Cut Image…"),
       tr("The surface of the current cut plane at true scale, with the growth field and ring lines as "
          "layers")},
      {ExportDialog::Kind::Volume, tr("&Volume…"),
       tr("The growth field or the colour through the whole block, as NRRD or OpenVDB")},
      {ExportDialog::Kind::DepthStack, tr("&Depth Stack…"),
       tr("A face after milling away 0 .. D mm in steps, as numbered PNGs with an index of depths")},
  };
  for (const auto& entry : entries) {
    QAction* action =
        exportMenu->addAction(entry.text, this, [this, kind = entry.kind] { showExportDialog(kind); });
    action->setToolTip(entry.tip);
    action->setStatusTip(entry.tip);
    exportActions_[static_cast<int>(entry.kind)] = action;
  }
  QAction* part = exportMenu->addAction(tr("&Part…"), this, [this] { showPartExportDialog(); });
  part->setStatusTip(
      tr("A mesh (OBJ, STL, PLY) placed in the block, baked with its wood as OBJ+MTL+PNG or "
         "glTF; shown in the 3D view while you place it"));
  exportMenu->addSeparator();
  exportMenu->addAction(tr("All Model Faces as PNG…"), this, &MainWindow::exportFaces);

  const auto forget = [this](int id) {
    const auto it = std::find(exportJobs_.begin(), exportJobs_.end(), id);
    if (it == exportJobs_.end()) return false;
    exportJobs_.erase(it);
    return true;
  };
  connect(jobs_, &JobRunner::jobFailed, this, [this, forget](int id, const QString& message) {
    if (!forget(id)) return;
    showError(tr("The export failed: %1").arg(message));
    emit exportFailed(message);
  });
  connect(jobs_, &JobRunner::jobFinished, this, [forget](int id) { forget(id); });
  connect(jobs_, &JobRunner::jobCancelled, this, [this, forget](int id) {
    if (forget(id)) emit exportFailed(tr("cancelled"));
  });
}

ExportDialog* MainWindow::showExportDialog(ExportDialog::Kind kind) {
  auto* dialog =
      new ExportDialog(kind, document_->project().block, document_->cutPlane().plane(), exportFolder(), this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    QSettings().setValue("export/folder", QFileInfo(dialog->path()).absolutePath());
    startExport(dialog->request());
  });
  dialog->open();  // window-modal, returns at once
  return dialog;
}

PartExportDialog* MainWindow::showPartExportDialog() {
  auto* dialog = new PartExportDialog(document_->project().block, exportFolder(), this);
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

int MainWindow::startExport(const ExportRequest& request) {
  const auto model = document_->model();
  const QString path = QString::fromStdString(request.out.string());
  const int id = jobs_->start(
      tr("Exporting %1").arg(QFileInfo(path).fileName()),
      [model, request](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        const ExportSummary summary = runExport(*model, request, progress);
        return QStringList{QString::fromStdString(summary.message), QString::fromStdString(summary.warning)};
      },
      [this, path](const QVariant& done) {
        const QString message = done.toStringList().value(0), warning = done.toStringList().value(1);
        logMessage("info", message);
        if (!warning.isEmpty()) logMessage("warning", warning);
        statusBar()->showMessage(message, 6000);
        emit exportFinished(path, message);
      },
      {}, false);
  exportJobs_.push_back(id);
  return id;
}

}  // namespace kerf
