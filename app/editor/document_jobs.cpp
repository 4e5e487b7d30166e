#include "document_jobs.hpp"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <algorithm>
#include <exception>

#include "io/image.hpp"
#include "params/builtin_presets.hpp"
#include "qt_image.hpp"
#include "render/renderers.hpp"
#include "util/error.hpp"

namespace kerf {

namespace {

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(path.toStdString());
}

QString documentName(const QString& path) {
  const QFileInfo info(path);
  return info.isDir() ? QDir(info.absoluteFilePath()).dirName() : info.completeBaseName();
}

}  // namespace

bool LoadedDocument::hasPhotos() const {
  return std::any_of(photos.begin(), photos.end(), [](const QImage& image) { return !image.isNull(); });
}

QString defaultDemoFolder() {
  return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/demo");
}

QString ensureDemo(const QString& folder, const DemoOptions& options, const Progress& progress) {
  // writeDemo writes demo.kerf last, so its presence means a complete demo.
  const QString project = QDir(folder).filePath(QStringLiteral("demo.kerf"));
  if (!QFileInfo::exists(project)) writeDemo(toPath(folder), options, progress);
  return project;
}

LoadedDocument loadDocumentFiles(const QString& path) {
  LoadedDocument document;
  document.path = path;
  try {
    if (path.isEmpty()) throw InputError("no document given");
    if (!QFileInfo::exists(path)) throw InputError("no such file or folder: " + path.toStdString());
    auto project = std::make_shared<Project>(loadDocument(toPath(path)));
    if (QFileInfo(path).isDir()) {
      if (const Preset* species = builtInPresetForSampleName(QDir(path).dirName().toStdString())) {
        project->params = species->applyTo(project->params);
        document.speciesId = QString::fromStdString(species->id);
        document.speciesName = QString::fromStdString(species->name);
      }
    }
    for (int i = 0; i < 6; ++i) {
      if (!project->facePhotos[i].empty()) document.photos[i] = toQImage(readImage(project->facePhotos[i]));
    }
    document.model = std::make_shared<const WoodModel>(*project);
    document.project = std::move(project);
    document.name = documentName(path);
  } catch (const std::exception& e) {  // InputError, and anything unexpected from the libraries
    document = LoadedDocument{};
    document.path = path;
    document.error = QString::fromStdString(e.what());
  }
  return document;
}

LoadedDocument loadDemo(const QString& folder, const DemoOptions& options, const Progress& progress) {
  try {
    return loadDocumentFiles(ensureDemo(folder, options, progress));
  } catch (const std::exception& e) {
    LoadedDocument document;
    document.path = folder;
    document.error = QStringLiteral("could not create the demo: ") + QString::fromStdString(e.what());
    return document;
  }
}

RenderedFaces renderModelFaces(const WoodModel& model, const RenderSettings& settings,
                               const Progress& progress) {
  RenderedFaces result;
  try {
    const std::array<Image, 6> faces = renderFaces(model, settings.pxPerMm, settings.samples, progress);
    for (int i = 0; i < 6; ++i) result.faces[i] = toQImage(faces[i]);
  } catch (const Cancelled&) {
    result.cancelled = true;
  } catch (const std::exception& e) {
    result.error = QString::fromStdString(e.what());
  }
  return result;
}

}  // namespace kerf
