#include "faces_controller.hpp"

#include <QAction>
#include <QActionGroup>
#include <QSlider>
#include <cmath>
#include <iterator>

#include "cut_view.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "job_runner.hpp"
#include "log_board_faces.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "viewport3d.hpp"

namespace kerf {

FacesController::FacesController(const EditorContext& context, RenderSettings settings, FacesView* facesView,
                                 Viewport3D* viewport, CutView* cutView)
    : EditorController(context),
      settings_(settings),
      facesView_(facesView),
      viewport_(viewport),
      cutView_(cutView) {
  connect(document_, &Document::ringUncertaintyChanged, this, &FacesController::showRingUncertainty);
}

void FacesController::setDisplayControls(QActionGroup* displays, QAction* toggleView, QSlider* slider) {
  displays_ = displays;
  toggleViewAction_ = toggleView;
  slider_ = slider;
  for (QAction* action : displays_->actions())
    connect(action, &QAction::triggered, this, [this, action] { chooseDisplay(action->data().toInt()); });
  connect(toggleViewAction_, &QAction::triggered, this, &FacesController::toggleView);
  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    if (displayMode_ == static_cast<int>(FaceDisplay::Split))
      facesView_->setSplitPosition(v / 100.0);
    else
      facesView_->setBlendOpacity(v / 100.0);
  });
  connect(facesView_, &FacesView::splitPositionChanged, this, [this] { updateFaceSlider(); });
}

void FacesController::beginDocument(bool freshView) {
  hasDocument_ = true;
  documentReadyPending_ = true;
  if (!freshView) return;
  displayChosenByUser_ = false;
  renderings_ = {};
}

void FacesController::showPlaceholder(const QString& text) {
  if (!hasDocument_) facesView_->setPlaceholderText(text);
}

void FacesController::showDocumentModel() {
  const auto model = document_->model();
  viewport_->setModel(model);
  cutView_->setModel(model);
  showRingUncertainty();
  renderFaces();
}

// How sure the fit is, over the cut: only while it belongs to the document's field.
void FacesController::showRingUncertainty() {
  const RingUncertainty* sure = document_->ringUncertainty();
  cutView_->setRingUncertainty(sure ? std::make_shared<const RingUncertainty>(*sure) : nullptr);
}

void FacesController::showPreview(std::shared_ptr<const WoodModel> model) {
  viewport_->setModel(model);
  cutView_->setModel(model);
  cutView_->setRingUncertainty(nullptr);  // a preview's field is not the one it was estimated for
  renderFacesOf(std::move(model));
}

// The model's faces for the faces view, progressively: a quarter-resolution preview within a few
// milliseconds, then full resolution with one sample per pixel, then the supersampled final picture.
// A newer edit cancels the running render, so a slider drag keeps showing fresh previews.
void FacesController::renderFaces() {
  if (!hasDocument_) return;
  if (document_->log()) {  // the board cut from the log
    renderBoardFaces();
    return;
  }
  renderFacesOf(document_->model());
}

void FacesController::renderFacesOf(std::shared_ptr<const WoodModel> model) {
  renderedModel_ = model;
  const RenderSettings settings = settings_;
  if (renderJob_ && jobs_->isRunning(renderJob_)) jobs_->cancel(renderJob_);
  renderJob_ = jobs_->start(
      tr("Rendering faces"),
      [model, settings](const Progress& progress, const JobRunner::Preview& preview) -> QVariant {
        const auto stage = [&](float pxPerMm, int samples, const Progress& stageProgress) {
          RenderedFaces faces = renderModelFaces(*model, RenderSettings{pxPerMm, samples}, stageProgress);
          if (faces.cancelled) throw Cancelled();
          if (!faces.error.isEmpty()) throw InputError(faces.error.toStdString());
          return faces.faces;
        };
        const Progress quiet{nullptr, progress.stop};
        preview(QVariant::fromValue(stage(settings.pxPerMm / 4.0f, 1, quiet)));
        if (settings.samples > 1) preview(QVariant::fromValue(stage(settings.pxPerMm, 1, quiet)));
        return QVariant::fromValue(stage(settings.pxPerMm, settings.samples, progress));
      },
      [this](const QVariant& result) { showRenderings(result, true); },
      [this](const QVariant& preview) { showRenderings(preview, false); }, false);
}

// The board's six faces: a quarter-resolution preview first, then full resolution; a newer edit
// (board moved, knot edited, parameter changed) cancels the running one.
void FacesController::renderBoardFaces() {
  renderedModel_.reset();
  const ProjectLog log = *document_->log();
  const WoodParameters params = document_->project().params;
  const float pxPerMm = settings_.pxPerMm;
  if (renderJob_ && jobs_->isRunning(renderJob_)) jobs_->cancel(renderJob_);
  renderJob_ = jobs_->start(
      tr("Rendering board"),
      [log, params, pxPerMm](const Progress& progress, const JobRunner::Preview& preview) -> QVariant {
        preview(QVariant::fromValue(
            renderLogBoardFaces(log, params, pxPerMm / 4.0f, Progress{nullptr, progress.stop})));
        return QVariant::fromValue(renderLogBoardFaces(log, params, pxPerMm, progress));
      },
      [this](const QVariant& faces) { showRenderings(faces, true); },
      [this](const QVariant& faces) { showRenderings(faces, false); }, false);
}

void FacesController::showRenderings(const QVariant& faces, bool final) {
  renderings_ = faces.value<std::array<QImage, 6>>();
  updateFacesView();
  if (!final) {
    emit facesPreviewed();
    return;
  }
  emit facesRendered();
  if (documentReadyPending_) {
    documentReadyPending_ = false;
    emit documentReady();
  }
}

void FacesController::setAppearanceFaces(std::shared_ptr<const WoodModel> forModel,
                                         const std::array<QImage, 6>& faces) {
  appearanceModel_ = std::move(forModel);
  appearanceFaces_ = faces;
  viewport_->setFaceAppearance(appearanceModel_, faces);
  updateFacesView();
}

bool FacesController::showsAppearanceFaces() const {
  return appearanceModel_ && appearanceModel_ == renderedModel_;
}

void FacesController::updateFacesView() {
  std::array<QImage, 6> shown = renderings_;
  if (showsAppearanceFaces())
    for (int i = 0; i < 6; ++i)
      if (!appearanceFaces_[i].isNull()) shown[i] = appearanceFaces_[i];
  facesView_->setRenderings(shown);
  const bool photos = document_->hasPhotos() && !document_->log();  // a log's board has no photos
  if (!displayChosenByUser_) displayMode_ = photos ? 0 : 1;
  if (!photos && displayMode_ != 1) displayMode_ = 1;  // nothing to show or blend but the model
  for (QAction* action : displays_->actions()) {
    action->setChecked(action->data().toInt() == displayMode_);
    action->setEnabled(photos || action->data().toInt() == 1);
  }
  facesView_->setDisplay(static_cast<FaceDisplay>(displayMode_));
  updateFaceSlider();
  toggleViewAction_->setEnabled(photos);
  toggleViewAction_->setText(showingPhotos() ? tr("Show &Model Rendering") : tr("Show &Photos"));
  const QString shortcut = toggleViewAction_->shortcut().toString(QKeySequence::NativeText);
  static const QString titles[] = {tr("Photos"), tr("Model rendering"), tr("Model over photos"),
                                   tr("Photo | model"), tr("Model against photo")};
  static_assert(std::size(titles) == kFaceDisplayCount);
  const QString toggle = photos ? tr("%1: photos / model").arg(shortcut) : QString();
  const bool split = displayMode_ == static_cast<int>(FaceDisplay::Split);
  facesView_->setCaption(hasDocument_ ? titles[displayMode_] : QString(),
                         split ? tr("drag the line · %1").arg(toggle) : toggle);
}

// One slider, two meanings: the model's opacity in Blend, the photo | model line in Split.
void FacesController::updateFaceSlider() {
  const bool split = displayMode_ == static_cast<int>(FaceDisplay::Split);
  const QSignalBlocker blocker(slider_);
  slider_->setEnabled(split || displayMode_ == static_cast<int>(FaceDisplay::Blend));
  slider_->setValue(static_cast<int>(
      std::lround(100 * (split ? facesView_->splitPosition() : facesView_->blendOpacity()))));
  const QString tip = split ? tr("Where the line between photo (left) and model (right) crosses the faces")
                            : tr("Opacity of the model over the photos in Blend mode");
  slider_->setToolTip(tip);
}

bool FacesController::showingPhotos() const {
  return facesView_->display() == FaceDisplay::Photos && document_->hasPhotos();
}

void FacesController::chooseDisplay(int display) {
  displayChosenByUser_ = true;
  setFaceDisplay(display);
}

void FacesController::setFaceDisplay(int display) {
  displayMode_ = display;
  updateFacesView();
}

void FacesController::toggleView() {
  chooseDisplay(showingPhotos() ? 1 : 0);
}

}  // namespace kerf
