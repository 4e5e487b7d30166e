#pragma once
// File > Import Photos, after the dialog: write the rectified faces at full size (a background job) and
// put them, with the block's new size, into the document as one undo step.
#include <QImage>
#include <QString>
#include <array>
#include <optional>

#include "geometry/block.hpp"
#include "io/face_photo_rectify.hpp"
#include "util/progress.hpp"

namespace kerf {

class Document;
class JobRunner;

// What the Import Photos dialog hands over.
struct PhotoImportPlan {
  Block block;
  float pxPerMm = 10.0f;                               // face images are the face's mm times this
  QString folder;                                      // where X_col.png are written (created if needed)
  std::array<std::optional<FacePhotoSetup>, 6> faces;  // A..F; empty: the face keeps its photo

  int faceCount() const;
  QString faceLetters() const;  // "A, B, E"
};

// Where face `face` is written: FOLDER/A_col.png .. (a Mokume-style sample folder).
QString importedFacePath(const QString& folder, FaceId face);

// The faces written, A..F (null/empty for faces not in the plan).
struct ImportedFaces {
  std::array<QString, 6> paths;
  std::array<QImage, 6> images;
};

// Reads each photo at full size, rectifies it to Block::faceImageSize(face, pxPerMm) and writes it
// atomically. Safe on any thread; reports progress per face and stops between faces on request
// (Cancelled). Throws InputError naming the photo or file.
ImportedFaces writeImportedFaces(const PhotoImportPlan& plan, const Progress& progress);

// The block's size and the new photos (other faces keep theirs) as one undo step.
void applyImportedFaces(Document& document, const PhotoImportPlan& plan, const ImportedFaces& faces);

// Runs writeImportedFaces on the runner ("Importing photos", with progress and Cancel), then
// applyImportedFaces on the GUI thread and `done`. Failures and cancelling are reported by the runner's
// signals for the returned job id.
int startPhotoImport(JobRunner& jobs, Document& document, const PhotoImportPlan& plan,
                     std::function<void()> done = {});

}  // namespace kerf
