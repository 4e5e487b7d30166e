#include "document_commands.hpp"

#include "document.hpp"

namespace kerf {

QUndoCommand* setParameterCommand(Document* document, std::size_t index, std::array<float, 3> before,
                                  std::array<float, 3> after, bool finished) {
  const ParamSpec& spec = parameterSchema()[index];
  // A no-change edit still closes an open drag (by merging); on its own the stack drops it.
  return new SwapValueCommand<std::array<float, 3>, Unchanged::Dropped>(
      [document, index](const std::array<float, 3>& value) { document->applyParameterValue(index, value); },
      before, after,
      QObject::tr("Change %1").arg(QString::fromUtf8(spec.label.data(), static_cast<int>(spec.label.size()))),
      {kParameterCommandBase + static_cast<int>(index), finished});
}

QUndoCommand* setAllParametersCommand(Document* document, const WoodParameters& before,
                                      const WoodParameters& after, const QString& text) {
  return new SwapValueCommand<WoodParameters, Unchanged::Dropped>(
      [document](const WoodParameters& params) { document->applyAllParameters(params); }, before, after,
      text);
}

QUndoCommand* setGrowthFieldCommand(Document* document, GrowthFieldValue before, GrowthFieldValue after,
                                    const QString& text) {
  return new SwapValueCommand<GrowthFieldValue>(
      [document](const GrowthFieldValue& field) {
        document->applyGrowthFieldValue(field.params, field.rates, field.knots);
      },
      std::move(before), std::move(after), text);
}

QUndoCommand* setCutPlaneCommand(Document* document, const CutPlaneSetting& before,
                                 const CutPlaneSetting& after, bool finished) {
  return new SwapValueCommand<CutPlaneSetting, Unchanged::Dropped>(
      [document](const CutPlaneSetting& setting) { document->applyCutPlane(setting); }, before, after,
      QObject::tr("Move cut plane"), {kCutPlaneCommand, finished});
}

QUndoCommand* setAnnotationsCommand(Document* document, Annotations before, Annotations after,
                                    const QString& text) {
  return new SwapValueCommand<Annotations>(
      [document](const Annotations& annotations) { document->applyAnnotations(annotations); },
      std::move(before), std::move(after), text);
}

QUndoCommand* replacePhotoCommand(Document* document, FaceId face, FacePhotoValue before,
                                  FacePhotoValue after) {
  return new SwapValueCommand<FacePhotoValue>(
      [document, face](const FacePhotoValue& photo) { document->applyPhoto(face, photo.path, photo.image); },
      std::move(before), std::move(after),
      QObject::tr("Replace photo of face %1").arg(QChar(faceLetter(face))));
}

QUndoCommand* setBlockAndPhotosCommand(Document* document, BlockAndPhotosValue before,
                                       BlockAndPhotosValue after, const QString& text) {
  return new SwapValueCommand<BlockAndPhotosValue>(
      [document](const BlockAndPhotosValue& value) {
        document->applyBlockAndPhotos(value.block, value.paths, value.images);
      },
      std::move(before), std::move(after), text);
}

QUndoCommand* setCutPhotoCommand(Document* document, CutPhotoValue before, CutPhotoValue after,
                                 const QString& text) {
  return new SwapValueCommand<CutPhotoValue>(
      [document](const CutPhotoValue& value) { document->applyCutPhoto(value.photo, value.image); },
      std::move(before), std::move(after), text);
}

}  // namespace kerf
