#include "photo_import.hpp"

#include <QDir>
#include <QFileInfo>
#include <QObject>
#include <QStringList>
#include <QVariant>
#include <filesystem>

#include "document.hpp"
#include "io/image.hpp"
#include "job_runner.hpp"
#include "qt_image.hpp"
#include "util/error.hpp"

namespace kerf {

int PhotoImportPlan::faceCount() const {
  int n = 0;
  for (const auto& face : faces) n += face.has_value();
  return n;
}

QString PhotoImportPlan::faceLetters() const {
  QStringList letters;
  for (FaceId face : kAllFaces)
    if (faces[faceIndex(face)]) letters << QString(QChar(faceLetter(face)));
  return letters.join(QStringLiteral(", "));
}

QString importedFacePath(const QString& folder, FaceId face) {
  return QDir(folder).filePath(QStringLiteral("%1_col.png").arg(QChar(faceLetter(face))));
}

ImportedFaces writeImportedFaces(const PhotoImportPlan& plan, const Progress& progress) {
  const int count = plan.faceCount();
  if (count == 0) throw InputError("no photo is assigned to a face");
  if (plan.folder.isEmpty()) throw InputError("no folder to write the faces to");
  std::filesystem::create_directories(plan.folder.toStdString());
  ImportedFaces result;
  int done = 0;
  for (FaceId face : kAllFaces) {
    const auto& setup = plan.faces[faceIndex(face)];
    if (!setup) continue;
    progress.throwIfCancelled();
    const Image image = rectifyFacePhoto(*setup, plan.block.faceImageSize(face, plan.pxPerMm));
    progress.throwIfCancelled();
    const QString path = importedFacePath(plan.folder, face);
    writeImage(path.toStdString(), image);
    result.paths[faceIndex(face)] = QFileInfo(path).absoluteFilePath();
    result.images[faceIndex(face)] = toQImage(image);
    progress.set(static_cast<double>(++done) / count);
  }
  return result;
}

void applyImportedFaces(Document& document, const PhotoImportPlan& plan, const ImportedFaces& faces) {
  std::array<QString, 6> paths;
  std::array<QImage, 6> images = document.photos();
  for (int i = 0; i < 6; ++i) {
    paths[i] = QString::fromStdString(document.project().facePhotos[i].string());
    if (plan.faces[i]) {
      paths[i] = faces.paths[i];
      images[i] = faces.images[i];
    }
  }
  document.replaceBlockAndPhotos(plan.block, paths, images,
                                 QObject::tr("Import photos of face %1").arg(plan.faceLetters()));
}

int startPhotoImport(JobRunner& jobs, Document& document, const PhotoImportPlan& plan,
                     std::function<void()> done) {
  Document* target = &document;
  return jobs.start(
      QObject::tr("Importing photos"),
      [plan](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(writeImportedFaces(plan, progress));
      },
      [target, plan, done](const QVariant& result) {
        applyImportedFaces(*target, plan, result.value<ImportedFaces>());
        if (done) done();
      },
      {}, false);
}

}  // namespace kerf
