// MainWindow: the Texture menu (the detail of the texture and its colours inferred from the face photos,
// core/texture/texture_inference.hpp, as `kerf-cli texture` does).
#include <QAction>
#include <QMenu>
#include <QMenuBar>

#include "cut_view.hpp"
#include "document.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"
#include "render/wood_model.hpp"
#include "texture_job.hpp"
#include "util/error.hpp"
#include "viewport3d.hpp"

namespace kerf {

void MainWindow::createTextureMenu() {
  QMenu* texture = menuBar()->addMenu(tr("&Texture"));
  texture->setToolTipsVisible(true);
  inferTextureAction_ = texture->addAction(tr("&Infer Texture from Photos"), this, &MainWindow::inferTexture);
  inferTextureAction_->setToolTip(tr(
      "Find the pores, rays and fibres (sizes, spacing, darkness) and the wood colours that make the faces "
      "look like the photos, each face compared with its own photo (end grain and side grain differ); fit "
      "the growth field first. Runs in the background (Esc cancels), the faces follow live; one undo step"));
  const auto ended = [this](int id, const QString& message) {
    if (id != textureJob_) return;
    textureJob_ = 0;
    modelChanged();  // back from the preview to the document's texture
    if (!message.isEmpty()) showError(tr("The texture could not be inferred: %1").arg(message));
    emit textureJobFailed(message.isEmpty() ? tr("cancelled") : message);
  };
  connect(jobs_, &JobRunner::jobFailed, this, ended);
  connect(jobs_, &JobRunner::jobCancelled, this, [ended](int id) { ended(id, {}); });
}

void MainWindow::inferTexture() {
  if (!hasDocument_ || !document_->hasPhotos() || document_->log()) {
    showError(
        tr("Infer Texture needs photos of the faces: open a sample folder (A_col.png .. F_col.png) or "
           "import photos, and fit the growth field (Rings ▸ Fit Growth Field) first."));
    emit textureJobFailed(lastError_);
    return;
  }
  if (textureJob_ && jobs_->isRunning(textureJob_)) return;  // already under way
  if (fitJob_ && jobs_->isRunning(fitJob_)) {
    showError(tr("The growth field is still being fitted; infer the texture when it has finished."));
    emit textureJobFailed(lastError_);
    return;
  }
  const Project& project = document_->project();
  const Block block = project.block;
  const WoodParameters current = project.params;
  const GrowthRates rates = project.effectiveRates();
  const std::array<QImage, 6> photos = document_->photos();
  TextureInferenceOptions options = textureOptions_;
  options.heldOut = project.heldOutFaces;  // leave-one-face-out: their photos are not used
  logMessage("info", tr("Inferring the texture from the face photos"));
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
bool MainWindow::applyTexture(std::shared_ptr<const TextureJobResult> texture) {
  for (const QString& line : texture->report) logMessage("info", line);
  try {
    document_->applyParameters(texture->params, tr("Infer texture"));
  } catch (const InputError& e) {
    showError(tr("The inferred texture is not valid: %1").arg(QString::fromUtf8(e.what())));
    modelChanged();
    emit textureJobFailed(lastError_);
    return false;
  }
  logMessage("info", tr("Texture inferred: loss %1 -> %2 (Ctrl+Z undoes it)")
                         .arg(texture->lossBefore, 0, 'f', 4)
                         .arg(texture->lossAfter, 0, 'f', 4));
  emit textureInferred();
  return true;
}

// The texture being inferred, on the faces, the 3D view and the cut before it is applied.
void MainWindow::showTexturePreview(const WoodParameters& params) {
  std::shared_ptr<const WoodModel> model;
  try {
    model = std::make_shared<const WoodModel>(document_->project().block, params,
                                              document_->project().effectiveRates());
  } catch (const InputError&) {
    return;
  }
  viewport_->setModel(model);
  cutView_->setModel(model);
  renderFacesOf(model);
  emit texturePreviewed();
}

}  // namespace kerf
