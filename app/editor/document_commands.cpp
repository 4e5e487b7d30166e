#include "document_commands.hpp"

#include "document.hpp"

namespace kerf {

SetParameterCommand::SetParameterCommand(Document* document, std::size_t index, std::array<float, 3> before,
                                         std::array<float, 3> after, bool finished)
    : document_(document), index_(index), before_(before), after_(after), finished_(finished) {
  const ParamSpec& spec = parameterSchema()[index];
  setText(QObject::tr("Change %1")
              .arg(QString::fromUtf8(spec.label.data(), static_cast<int>(spec.label.size()))));
  // A no-change edit still closes an open drag (by merging); on its own the stack drops it.
  setObsolete(before == after);
}

void SetParameterCommand::undo() {
  document_->applyParameterValue(index_, before_);
}
void SetParameterCommand::redo() {
  document_->applyParameterValue(index_, after_);
}

bool SetParameterCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = static_cast<const SetParameterCommand*>(other);
  if (finished_ || next->index_ != index_) return false;
  after_ = next->after_;
  finished_ = next->finished_;
  setObsolete(after_ == before_);  // dragged back to where it started
  return true;
}

SetAllParametersCommand::SetAllParametersCommand(Document* document, const WoodParameters& before,
                                                 const WoodParameters& after, const QString& text)
    : document_(document), before_(before), after_(after) {
  setText(text);
  setObsolete(before == after);
}

void SetAllParametersCommand::undo() {
  document_->applyAllParameters(before_);
}
void SetAllParametersCommand::redo() {
  document_->applyAllParameters(after_);
}

SetGrowthFieldCommand::SetGrowthFieldCommand(Document* document, Field before, Field after,
                                             const QString& text)
    : document_(document), before_(std::move(before)), after_(std::move(after)) {
  setText(text);
}

void SetGrowthFieldCommand::undo() {
  document_->applyGrowthFieldValue(before_.params, before_.rates, before_.knots);
}
void SetGrowthFieldCommand::redo() {
  document_->applyGrowthFieldValue(after_.params, after_.rates, after_.knots);
}

SetCutPlaneCommand::SetCutPlaneCommand(Document* document, const CutPlaneSetting& before,
                                       const CutPlaneSetting& after, bool finished)
    : document_(document), before_(before), after_(after), finished_(finished) {
  setText(QObject::tr("Move cut plane"));
  setObsolete(before == after);
}

void SetCutPlaneCommand::undo() {
  document_->applyCutPlane(before_);
}
void SetCutPlaneCommand::redo() {
  document_->applyCutPlane(after_);
}

bool SetCutPlaneCommand::mergeWith(const QUndoCommand* other) {
  if (finished_) return false;
  const auto* next = static_cast<const SetCutPlaneCommand*>(other);
  after_ = next->after_;
  finished_ = next->finished_;
  setObsolete(after_ == before_);
  return true;
}

SetAnnotationsCommand::SetAnnotationsCommand(Document* document, Annotations before, Annotations after,
                                             const QString& text)
    : document_(document), before_(std::move(before)), after_(std::move(after)) {
  setText(text);
}

void SetAnnotationsCommand::undo() {
  document_->applyAnnotations(before_);
}
void SetAnnotationsCommand::redo() {
  document_->applyAnnotations(after_);
}

ReplacePhotoCommand::ReplacePhotoCommand(Document* document, FaceId face, QString beforePath,
                                         QImage beforeImage, QString afterPath, QImage afterImage)
    : document_(document),
      face_(face),
      beforePath_(std::move(beforePath)),
      afterPath_(std::move(afterPath)),
      beforeImage_(std::move(beforeImage)),
      afterImage_(std::move(afterImage)) {
  setText(QObject::tr("Replace photo of face %1").arg(QChar(faceLetter(face))));
}

void ReplacePhotoCommand::undo() {
  document_->applyPhoto(face_, beforePath_, beforeImage_);
}
void ReplacePhotoCommand::redo() {
  document_->applyPhoto(face_, afterPath_, afterImage_);
}

SetBlockAndPhotosCommand::SetBlockAndPhotosCommand(Document* document, const Block& beforeBlock,
                                                   std::array<QString, 6> beforePaths,
                                                   std::array<QImage, 6> beforeImages,
                                                   const Block& afterBlock, std::array<QString, 6> afterPaths,
                                                   std::array<QImage, 6> afterImages, const QString& text)
    : document_(document),
      beforeBlock_(beforeBlock),
      afterBlock_(afterBlock),
      beforePaths_(std::move(beforePaths)),
      afterPaths_(std::move(afterPaths)),
      beforeImages_(std::move(beforeImages)),
      afterImages_(std::move(afterImages)) {
  setText(text);
}

void SetBlockAndPhotosCommand::undo() {
  document_->applyBlockAndPhotos(beforeBlock_, beforePaths_, beforeImages_);
}
void SetBlockAndPhotosCommand::redo() {
  document_->applyBlockAndPhotos(afterBlock_, afterPaths_, afterImages_);
}

}  // namespace kerf
