// FilesController: opening, saving, the recent files, recovery and a photo dropped on a face.
#include "files_controller.hpp"

#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QStandardPaths>

#include "autosave.hpp"
#include "document.hpp"
#include "faces_controller.hpp"
#include "job_runner.hpp"
#include "qt_image.hpp"
#include "recent_files.hpp"
#include "util/error.hpp"

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

FilesController::FilesController(const EditorContext& context, FacesController* faces)
    : EditorController(context), faces_(faces) {
  autosave_ = new Autosave(document_, {}, 5000, this);
  connect(autosave_, &Autosave::failed, this, [this](const QString& m) { log("warning", m); });
  connectImport();
}

void FilesController::setRecentMenu(QMenu* menu) {
  recent_ = new RecentFiles(menu, this);
  connect(recent_, &RecentFiles::openRequested, this, &FilesController::openInstead);
}

DemoOptions FilesController::demoOptions() {
  DemoOptions options;
  options.facePixels = 256;
  return options;
}

void FilesController::chooseDocument() {
  if (!maybeSave()) return;
  const QString chosen = QFileDialog::getOpenFileName(
      window_, tr("Open a project, or any face photo of a sample folder"), documentsFolder(),
      tr("Projects and face photos (*.kerf *_col.png *_col.jpg *_col.jpeg *_col.tif *_col.tiff);;"
         "Kerf projects (*.kerf);;All files (*)"));
  if (!chosen.isEmpty()) openDocument(documentPathFor(chosen));
}

void FilesController::openDocument(const QString& path) {
  startLoad(tr("Opening %1").arg(QFileInfo(path).fileName()),
            [path](const Progress&) { return loadDocumentFiles(path); });
}

void FilesController::openDemo(const QString& folder, const DemoOptions& options) {
  startLoad(tr("Preparing the demo block"),
            [folder, options](const Progress& progress) { return loadDemo(folder, options, progress); });
}

void FilesController::startLoad(const QString& what, std::function<LoadedDocument(const Progress&)> load) {
  faces_->showPlaceholder(what + QStringLiteral("…"));
  jobs_->start(
      what,
      [load](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(load(progress));
      },
      [this](const QVariant& result) { documentLoaded(result.value<LoadedDocument>()); }, {}, false);
}

void FilesController::documentLoaded(const LoadedDocument& loaded) {
  if (!loaded.ok()) {
    showError(loaded.error);
    emit documentFailed(loaded.error);
    return;
  }
  // A .kerf file is the document's file; a sample folder or the demo cache has none yet.
  const bool isProjectFile = QFileInfo(loaded.path).suffix().compare("kerf", Qt::CaseInsensitive) == 0 &&
                             !loaded.path.startsWith(defaultDemoFolder());
  faces_->beginDocument(true);
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
  log("info", tr("Opened %1").arg(loaded.path));
  emit speciesOpened(loaded.speciesId);
  if (!loaded.speciesId.isEmpty())
    log("info",
        tr("Species: %1, from the folder's name (the Preset box chooses another)").arg(loaded.speciesName));
  emit documentOpened(loaded.path);
  const FaceSet& heldOut = loaded.project->heldOutFaces;
  if (!heldOut.empty())
    log("info", tr("Held out (leave-one-face-out): face %1. Detect Rings, Fit Growth Field and Infer "
                   "Texture use nothing of its photo, so its rendering is a prediction")
                    .arg(QString::fromStdString(heldOut.letters())));
}

bool FilesController::save() {
  if (document_->filePath().isEmpty()) return saveAs();
  return saveAs(document_->filePath());
}

bool FilesController::saveAs(QString path) {
  if (path.isEmpty()) {
    const QString suggested = documentsFolder() + "/" + document_->name() + ".kerf";
    path = QFileDialog::getSaveFileName(window_, tr("Save Project"), suggested, tr("Kerf projects (*.kerf)"));
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
  log("info", tr("Saved %1").arg(path));
  emit statusShown(tr("Saved %1").arg(QFileInfo(path).fileName()), 4000);
  return true;
}

bool FilesController::maybeSave() {
  if (!document_->isModified() || !askBeforeDiscarding_) return true;
  const auto answer = QMessageBox::warning(
      window_, tr("Kerf"), tr("%1 has unsaved changes. Save them?").arg(document_->name()),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

void FilesController::offerRecovery() {
  const QStringList leftovers = autosave_->leftovers();
  if (leftovers.isEmpty()) return;
  const QString newest = leftovers.front();
  const QString original = Autosave::originalPathOf(newest);
  const auto answer = QMessageBox::question(
      window_, tr("Recover unsaved work?"),
      tr("Kerf did not close properly last time. Unsaved changes to %1 were kept. Recover them?")
          .arg(original.isEmpty() ? tr("an untitled document") : original),
      QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
  if (answer == QMessageBox::Yes) {
    recover(newest);
  } else {
    for (const QString& file : leftovers) QFile::remove(file);
  }
}

void FilesController::recover(const QString& autosaveFile) {
  try {
    const Project project = loadProject(autosaveFile.toStdString());
    LoadedDocument loaded = loadDocumentFiles(autosaveFile);  // reads the photos the copy refers to
    if (!loaded.ok()) throw InputError(loaded.error.toStdString());
    const QString original = Autosave::originalPathOf(autosaveFile);
    faces_->beginDocument(false);
    document_->reset(project, original,
                     original.isEmpty() ? tr("recovered") : QFileInfo(original).completeBaseName(),
                     loaded.photos);
    document_->markModified();  // recovered work is unsaved until the user saves it
    QFile::remove(autosaveFile);
    log("info", tr("Recovered unsaved work from %1").arg(autosaveFile));
  } catch (const InputError& e) {
    showError(tr("The autosaved copy could not be recovered: %1").arg(QString::fromUtf8(e.what())));
  }
}

void FilesController::openInstead(const QString& path) {
  if (maybeSave()) openDocument(path);
}

void FilesController::dropPhoto(FaceId face, const QString& path) {
  jobs_->start(
      tr("Loading photo"),
      [path](const Progress&, const JobRunner::Preview&) -> QVariant {
        const QImage image = toQImage(readImage(path.toStdString()));
        return image;
      },
      [this, face, path](const QVariant& image) {
        document_->replacePhoto(face, QFileInfo(path).absoluteFilePath(), image.value<QImage>());
        log("info", tr("Face %1: photo %2").arg(QChar(faceLetter(face))).arg(QFileInfo(path).fileName()));
      },
      {}, false);
}

}  // namespace kerf
