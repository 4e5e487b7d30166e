// MainWindow: menus, opening, saving, recovery and exports.
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QStandardPaths>
#include <QStatusBar>

#include "autosave.hpp"
#include "cut_view.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "io/image.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"
#include "parameter_panel.hpp"
#include "qt_image.hpp"
#include "recent_files.hpp"
#include "render/renderers.hpp"
#include "util/error.hpp"
#include "viewport3d.hpp"
#include "window_layout.hpp"

namespace kerf {
namespace {

// The file dialog picks files, so a sample folder is opened by picking one of its face photos.
QString documentPathFor(const QString& chosen) {
  const QFileInfo info(chosen);
  return info.suffix().compare("kerf", Qt::CaseInsensitive) == 0 ? chosen : info.absolutePath();
}

// Through the block's centre, oblique to the faces, so it shows the rings' cones as a saw would.
constexpr CutPlaneSetting kDefaultCut{0.0f, 35.0f, 20.0f};

QString documentsFolder() {
  return QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
}

}  // namespace

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->setObjectName("fileMenu");
  file->addAction(tr("Open &Demo Block"), this, [this] {
    if (maybeSave()) openDemo(defaultDemoFolder());
  });
  QAction* open = file->addAction(tr("&Open Project or Sample Folder…"), this, &MainWindow::chooseDocument);
  open->setShortcut(QKeySequence::Open);
  recent_ = new RecentFiles(file->addMenu(tr("Open &Recent")), this);
  file->addAction(createImportAction());
  createLogActions(file);  // main_window_log.cpp
  connect(recent_, &RecentFiles::openRequested, this, [this](const QString& path) {
    if (maybeSave()) openDocument(path);
  });
  file->addSeparator();
  QAction* saveAction = file->addAction(tr("&Save"), this, [this] { save(); });
  saveAction->setShortcut(QKeySequence::Save);
  QAction* saveAsAction = file->addAction(tr("Save &As…"), this, [this] { saveAs(); });
  saveAsAction->setShortcut(QKeySequence::SaveAs);
  file->addSeparator();
  QMenu* exportMenu = file->addMenu(tr("&Export"));
  createExportActions(exportMenu);  // main_window_export.cpp
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  undoAction_ = document_->undoStack()->createUndoAction(this, tr("&Undo"));
  undoAction_->setShortcut(QKeySequence::Undo);
  redoAction_ = document_->undoStack()->createRedoAction(this, tr("&Redo"));
  redoAction_->setShortcuts({QKeySequence::Redo, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)});
  edit->addAction(undoAction_);
  edit->addAction(redoAction_);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  toggleViewAction_ = view->addAction(tr("Show &Model Rendering"), this, &MainWindow::toggleView);
  toggleViewAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
  toggleViewAction_->setEnabled(false);
  QMenu* faces = view->addMenu(tr("&Faces Show"));
  faces->addActions(displayGroup_->actions());
  showPhotosOn3dAction_ = view->addAction(tr("Photos on the 3D &Block"));
  showPhotosOn3dAction_->setCheckable(true);
  showPhotosOn3dAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
  showPhotosOn3dAction_->setToolTip(
      tr("Project the face photos onto the 3D block to compare them with the model"));
  connect(showPhotosOn3dAction_, &QAction::toggled, viewport_, &Viewport3D::setShowPhotos);
  view->addAction(tr("Reset 3D &Camera"), viewport_, &Viewport3D::resetCamera)->setShortcut(Qt::Key_Home);
  showContoursAction_ = view->addAction(tr("Show Ring &Traces"));
  showContoursAction_->setCheckable(true);
  showContoursAction_->setChecked(true);
  showContoursAction_->setEnabled(false);
  showContoursAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
  showContoursAction_->setToolTip(
      tr("Draw the ring traces (detected and your own) and knot marks over the faces"));
  connect(showContoursAction_, &QAction::toggled, facesView_, &FacesView::setOverlayVisible);
  view->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());
  view->addAction(layout_->resetAction());

  createRingsMenu();
  createTextureMenu();

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About Kerf"), this, [this] {
    QMessageBox::about(this, tr("About Kerf"),
                       tr("<b>Kerf</b> %1<br>An editor for solid wood: the annual rings and texture inside a "
                          "block, from photos of its faces or from scratch.")
                           .arg(QApplication::applicationVersion()));
  });
}

void MainWindow::chooseDocument() {
  if (!maybeSave()) return;
  const QString chosen = QFileDialog::getOpenFileName(
      this, tr("Open a project, or any face photo of a sample folder"), documentsFolder(),
      tr("Projects and face photos (*.kerf *_col.png *_col.jpg *_col.jpeg *_col.tif *_col.tiff);;"
         "Kerf projects (*.kerf);;All files (*)"));
  if (!chosen.isEmpty()) openDocument(documentPathFor(chosen));
}

void MainWindow::openDocument(const QString& path) {
  startLoad(tr("Opening %1").arg(QFileInfo(path).fileName()),
            [path](const Progress&) { return loadDocumentFiles(path); });
}

void MainWindow::openDemo(const QString& folder, const DemoOptions& options) {
  startLoad(tr("Preparing the demo block"),
            [folder, options](const Progress& progress) { return loadDemo(folder, options, progress); });
}

void MainWindow::startLoad(const QString& what, std::function<LoadedDocument(const Progress&)> load) {
  if (!hasDocument_) facesView_->setPlaceholderText(what + QStringLiteral("…"));
  jobs_->start(
      what,
      [load](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(load(progress));
      },
      [this](const QVariant& result) { documentLoaded(result.value<LoadedDocument>()); }, {}, false);
}

void MainWindow::documentLoaded(const LoadedDocument& loaded) {
  if (!loaded.ok()) {
    showError(loaded.error);
    emit documentFailed(loaded.error);
    return;
  }
  // A .kerf file is the document's file; a sample folder or the demo cache has none yet.
  const bool isProjectFile = QFileInfo(loaded.path).suffix().compare("kerf", Qt::CaseInsensitive) == 0 &&
                             !loaded.path.startsWith(defaultDemoFolder());
  hasDocument_ = true;
  documentReadyPending_ = true;
  displayChosenByUser_ = false;
  renderings_ = {};
  Project project = *loaded.project;
  // The cut is why a woodworker opens Kerf: a document that never placed one opens with a default cut
  // shown (a view setting, so the document stays unmodified).
  if (!project.cutPlane) {
    project.cutPlane = kDefaultCut;
    project.cutEnabled = true;
  }
  document_->reset(project, isProjectFile ? QFileInfo(loaded.path).absoluteFilePath() : QString(),
                   loaded.name, loaded.photos);
  if (isProjectFile || QFileInfo(loaded.path).isDir()) recent_->add(loaded.path);
  logMessage("info", tr("Opened %1").arg(loaded.path));
  parameterPanel_->setCurrentPreset(loaded.speciesId);
  if (!loaded.speciesId.isEmpty())
    logMessage(
        "info",
        tr("Species: %1, from the folder's name (the Preset box chooses another)").arg(loaded.speciesName));
  emit documentOpened(loaded.path);
  const FaceSet& heldOut = loaded.project->heldOutFaces;
  if (!heldOut.empty())
    logMessage("info", tr("Held out (leave-one-face-out): face %1. Detect Rings, Fit Growth Field and Infer "
                          "Texture use nothing of its photo, so its rendering is a prediction")
                           .arg(QString::fromStdString(heldOut.letters())));
}

bool MainWindow::save() {
  if (document_->filePath().isEmpty()) return saveAs();
  return saveAs(document_->filePath());
}

bool MainWindow::saveAs(QString path) {
  if (path.isEmpty()) {
    const QString suggested = documentsFolder() + "/" + document_->name() + ".kerf";
    path = QFileDialog::getSaveFileName(this, tr("Save Project"), suggested, tr("Kerf projects (*.kerf)"));
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += ".kerf";
  }
  try {
    document_->saveAs(path);
  } catch (const InputError& e) {
    showError(tr("The project was not saved: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
  autosave_->discardCurrent();
  recent_->add(path);
  logMessage("info", tr("Saved %1").arg(path));
  statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 4000);
  return true;
}

bool MainWindow::maybeSave() {
  if (!document_->isModified() || !askBeforeDiscarding_) return true;
  const auto answer =
      QMessageBox::warning(this, tr("Kerf"), tr("%1 has unsaved changes. Save them?").arg(document_->name()),
                           QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

void MainWindow::offerRecovery() {
  const QStringList leftovers = autosave_->leftovers();
  if (leftovers.isEmpty()) return;
  const QString newest = leftovers.front();
  const QString original = Autosave::originalPathOf(newest);
  const auto answer = QMessageBox::question(
      this, tr("Recover unsaved work?"),
      tr("Kerf did not close properly last time. Unsaved changes to %1 were kept. Recover them?")
          .arg(original.isEmpty() ? tr("an untitled document") : original),
      QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
  if (answer == QMessageBox::Yes) {
    recover(newest);
  } else {
    for (const QString& file : leftovers) QFile::remove(file);
  }
}

void MainWindow::recover(const QString& autosaveFile) {
  try {
    const Project project = loadProject(autosaveFile.toStdString());
    LoadedDocument loaded = loadDocumentFiles(autosaveFile);  // reads the photos the copy refers to
    if (!loaded.ok()) throw InputError(loaded.error.toStdString());
    const QString original = Autosave::originalPathOf(autosaveFile);
    hasDocument_ = true;
    documentReadyPending_ = true;
    document_->reset(project, original,
                     original.isEmpty() ? tr("recovered") : QFileInfo(original).completeBaseName(),
                     loaded.photos);
    document_->markModified();  // recovered work is unsaved until the user saves it
    QFile::remove(autosaveFile);
    logMessage("info", tr("Recovered unsaved work from %1").arg(autosaveFile));
  } catch (const InputError& e) {
    showError(tr("The autosaved copy could not be recovered: %1").arg(QString::fromUtf8(e.what())));
  }
}

void MainWindow::exportFaces() {
  const QString folder =
      QFileDialog::getExistingDirectory(this, tr("Export model faces to folder"), documentsFolder());
  if (folder.isEmpty()) return;
  const auto model = document_->model();
  const float pxPerMm = settings_.pxPerMm * 2;
  jobs_->start(
      tr("Exporting faces"),
      [model, folder, pxPerMm](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        const auto images = kerf::renderFaces(*model, pxPerMm, 2, progress);
        for (FaceId face : kAllFaces) {
          writeImage((QDir(folder).filePath(QString("%1.png").arg(QChar(faceLetter(face))))).toStdString(),
                     images[faceIndex(face)]);
        }
        return folder;
      },
      [this](const QVariant& done) { logMessage("info", tr("Faces written to %1").arg(done.toString())); },
      {}, false);
}

}  // namespace kerf
