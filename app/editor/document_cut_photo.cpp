// Document: the photo of the real cut (docs/editor.md, "Comparing a photo of the cut").
#include "document.hpp"
#include "document_commands.hpp"

namespace kerf {

void Document::setCutPhoto(std::optional<CutPhoto> photo, const QImage& image, const QString& undoText) {
  undo_.push(
      setCutPhotoCommand(this, {project_.cutPhoto, cutPhotoImage_}, {std::move(photo), image}, undoText));
}

void Document::restoreCutPhotoImage(const QImage& image) {
  cutPhotoImage_ = image;
  emit cutPhotoChanged();
}

void Document::applyCutPhoto(const std::optional<CutPhoto>& photo, const QImage& image) {
  project_.cutPhoto = photo;
  cutPhotoImage_ = image;
  emit cutPhotoChanged();
}

}  // namespace kerf
