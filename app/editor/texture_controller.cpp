// TextureController: the Texture menu's work (the detail of the texture and its colours inferred from the
// face photos, core/texture/texture_inference.hpp, as `kerf-cli texture` does).
#include "texture_controller.hpp"

#include "document.hpp"
#include "faces_controller.hpp"
#include "job_runner.hpp"
#include "render/wood_model.hpp"
#include "rings_controller.hpp"
#include "util/error.hpp"

namespace kerf {

TextureController::TextureController(const EditorContext& context, FacesController* faces,
                                     const RingsController* rings)
    : EditorController(context), faces_(faces), rings_(rings) {
  connect(jobs_, &JobRunner::jobFailed, this, &TextureController::ended);
  connect(jobs_, &JobRunner::jobCancelled, this, [this](int id) { ended(id, {}); });
}

bool TextureController::isRunning() const {
  return textureJob_ && jobs_->isRunning(textureJob_);
}

void TextureController::fail(const QString& message) {
  showError(message);
  emit textureJobFailed(message);
}

void TextureController::ended(int id, const QString& message) {
  if (id != textureJob_) return;
  textureJob_ = 0;
  faces_->showDocumentModel();  // back from the preview to the document's texture
  if (!message.isEmpty()) showError(tr("The texture could not be inferred: %1").arg(message));
  emit textureJobFailed(message.isEmpty() ? tr("cancelled") : message);
}

void TextureController::inferTexture() {
  if (!faces_->hasDocument() || !document_->hasPhotos() || document_->log()) {
    fail(
        tr("Infer Texture needs photos of the faces: open a sample folder (A_col.png .. F_col.png) or "
           "import photos, and fit the growth field (Rings ▸ Fit Growth Field) first."));
    return;
  }
  if (textureJob_ && jobs_->isRunning(textureJob_)) return;  // already under way
  if (rings_->isFitting()) {
    fail(tr("The growth field is still being fitted; infer the texture when it has finished."));
    return;
  }
  const Project& project = document_->project();
  const Block block = project.block;
  const WoodParameters current = project.params;
  const GrowthRates rates = project.effectiveRates();
  const std::array<QImage, 6> photos = document_->photos();
  TextureInferenceOptions options = textureOptions_;
  options.heldOut = project.heldOutFaces;  // leave-one-face-out: their photos are not used
  log("info", tr("Inferring the texture from the face photos"));
  textureJob_ = jobs_->start(
      tr("Inferring texture"),
      [block, current, rates, photos, options](const Progress& progress,
                                               const JobRunner::Preview& preview) -> QVariant {
        const TexturePreview live = [&preview](const WoodParameters& params) {
          preview(QVariant::fromValue(std::make_shared<const WoodParameters>(params)));
        };
        return QVariant::fromValue(std::make_shared<const TextureJobResult>(
            inferTextureFromPhotos(block, current, rates, photos, options, progress, live)));
      },
      [this](const QVariant& result) {
        textureJob_ = 0;
        applyTexture(result.value<std::shared_ptr<const TextureJobResult>>());
      },
      [this](const QVariant& preview) {
        const auto params = preview.value<std::shared_ptr<const WoodParameters>>();
        if (params && textureJob_) showTexturePreview(*params);
      },
      false);
}

// An inferred texture that has landed: applied as one undo step.
bool TextureController::applyTexture(std::shared_ptr<const TextureJobResult> texture) {
  for (const QString& line : texture->report) log("info", line);
  try {
    document_->applyParameters(texture->params, tr("Infer texture"));
  } catch (const InputError& e) {
    const QString message = tr("The inferred texture is not valid: %1").arg(QString::fromUtf8(e.what()));
    showError(message);
    faces_->showDocumentModel();
    emit textureJobFailed(message);
    return false;
  }
  log("info", tr("Texture inferred: loss %1 -> %2 (Ctrl+Z undoes it)")
                  .arg(texture->lossBefore, 0, 'f', 4)
                  .arg(texture->lossAfter, 0, 'f', 4));
  emit textureInferred();
  return true;
}

// The texture being inferred, on the faces, the 3D view and the cut before it is applied.
void TextureController::showTexturePreview(const WoodParameters& params) {
  std::shared_ptr<const WoodModel> model;
  try {
    model = std::make_shared<const WoodModel>(document_->project().block, params,
                                              document_->project().effectiveRates());
  } catch (const InputError&) {
    return;
  }
  faces_->showPreview(model);
  emit texturePreviewed();
}

}  // namespace kerf
