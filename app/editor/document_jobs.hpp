#pragma once
// The editor's slow work, run off the GUI thread (QtConcurrent): generating the demo, loading a
// document with its photos, rendering the model's faces. Each function is self-contained (no
// QObject, no shared mutable state) and reports failure in its result instead of throwing, so the
// GUI can show the message and keep the current document.
#include <QImage>
#include <QString>
#include <array>
#include <memory>

#include "demo/demo_block.hpp"
#include "io/project.hpp"
#include "render/wood_model.hpp"
#include "util/progress.hpp"

namespace kerf {

struct RenderSettings {
  float pxPerMm = 6.4f;  // Mokume's 256 px per 40 mm
  int samples = 2;       // per pixel side
};

struct LoadedDocument {
  QString path;  // as opened: a .kerf file or a sample folder
  QString name;  // for the title bar
  std::shared_ptr<const Project> project;
  std::shared_ptr<const WoodModel> model;  // built (and validated) while loading
  std::array<QImage, 6> photos;            // A..F; null where a face has no photo
  QString error;                           // set instead of the above on failure
  // A sample folder named by a Mokume code (CN03) starts from that species' preset, as `kerf-cli fit`
  // does: its id and name, empty when the name says no species (or for a project, which keeps its wood).
  QString speciesId, speciesName;

  bool ok() const { return error.isEmpty(); }
  bool hasPhotos() const;
};

struct RenderedFaces {
  std::array<QImage, 6> faces;  // A..F
  QString error;
  bool cancelled = false;
};

// The folder the editor keeps its demo in (QStandardPaths::CacheLocation + "/demo").
QString defaultDemoFolder();

// Writes the demo into `folder` unless its project is already there; returns the project path.
// Throws InputError, Cancelled.
QString ensureDemo(const QString& folder, const DemoOptions& options, const Progress& progress = {});

// Reads a project or sample folder (kerf::loadDocument), its photos, and builds the model.
LoadedDocument loadDocumentFiles(const QString& path);

// ensureDemo + loadDocumentFiles, with any error in the result.
LoadedDocument loadDemo(const QString& folder, const DemoOptions& options, const Progress& progress = {});

RenderedFaces renderModelFaces(const WoodModel& model, const RenderSettings& settings,
                               const Progress& progress = {});

}  // namespace kerf
