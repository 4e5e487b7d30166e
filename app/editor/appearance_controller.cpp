#include "appearance_controller.hpp"

#include <QKeySequence>
#include <algorithm>

#include "appearance/photo_true_appearance.hpp"
#include "appearance/photo_true_source.hpp"
#include "cut_view.hpp"
#include "document.hpp"
#include "faces_controller.hpp"
#include "job_runner.hpp"
#include "qt_image.hpp"
#include "util/error.hpp"
#include "viewport3d.hpp"

namespace kerf {

// The photos' guidance on one model: what every photo-true surface of that model is made from.
struct PhotoTrueSurfaces {
  std::shared_ptr<const WoodModel> model;
  std::unique_ptr<const PhotoTrueAppearance> appearance;  // refers to *model
};

namespace {

struct FacesUpdate {
  std::shared_ptr<const PhotoTrueSurfaces> source;
  std::array<QImage, 6> faces;  // null where not made yet
};

std::shared_ptr<const PhotoTrueSurfaces> makeSource(std::shared_ptr<const WoodModel> model,
                                                    const std::array<QImage, 6>& photos,
                                                    const FaceSet& heldOut, const Progress& progress) {
  std::array<Image, 6> images;
  for (int i = 0; i < 6; ++i)
    if (!heldOut.contains(kAllFaces[i])) images[i] = fromQImage(photos[i]);
  auto source = std::make_shared<PhotoTrueSurfaces>();
  source->model = std::move(model);
  // The model's seed, as kerf-cli's render-faces, render-cut and export: the same surfaces everywhere.
  source->appearance = std::make_unique<const PhotoTrueAppearance>(
      *source->model, std::move(images), heldOut, photoTrueOptionsFor(*source->model), progress);
  return source;
}

// The cut at the photos' own resolution (they hold no finer detail; the panel scales it).
CutAppearance makeCut(const PhotoTrueSurfaces& source, const CutPlaneSetting& setting,
                      const Progress& progress) {
  const CutPlane plane = setting.plane();
  const float pxPerMm = source.appearance->synthesisPxPerMm();
  CutAppearance cut{source.model, setting, {}};
  cut.surface.image = toQImage(source.appearance->renderCut(plane, pxPerMm, progress));
  cut.surface.grid = cutGrid(source.model->block(), plane, pxPerMm);
  return cut;
}

}  // namespace

AppearanceController::AppearanceController(const EditorContext& context, RenderSettings settings,
                                           FacesController* faces, CutView* cutView, Viewport3D* viewport)
    : EditorController(context),
      settings_(settings),
      faces_(faces),
      cutView_(cutView),
      viewport_(viewport),
      photoTrueAction_(new QAction(tr("&Photo-true Appearance"), this)) {
  photoTrueAction_->setCheckable(true);
  photoTrueAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
  photoTrueAction_->setToolTip(
      tr("Show the block made of its own photos, re-grown along the fitted growth rings: the real pores, "
         "rays, colour and sheen of this board on every face and cut, instead of the procedural wood. Made "
         "in the background after each change (the procedural wood shows meanwhile); saved with the "
         "project"));
  connect(photoTrueAction_, &QAction::triggered, this,
          [this](bool on) { document_->setAppearance(on ? Appearance::Photo : Appearance::Procedural); });
  settle_.setSingleShot(true);
  settle_.setInterval(kSettleMs);
  connect(&settle_, &QTimer::timeout, this, &AppearanceController::startFaces);
  for (auto signal : {&Document::modelChanged, &Document::appearanceChanged, &Document::logChanged,
                      &Document::documentReset})
    connect(document_, signal, this, &AppearanceController::documentChanged);
  connect(document_, &Document::photosChanged, this, [this] {  // the same model, other exemplars
    source_.reset();
    cuts_.clear();
    documentChanged();
  });
  cutSettle_.setSingleShot(true);
  cutSettle_.setInterval(kSettleMs);
  connect(&cutSettle_, &QTimer::timeout, this, &AppearanceController::startCut);
  connect(document_, &Document::cutPlaneChanged, this, [this] {
    if (wanted() && source_) cutSettle_.start();  // without a source the faces job starts the cut
  });
  connect(jobs_, &JobRunner::jobFailed, this, [this](int id, const QString& message) {
    if (id == facesJob_ || id == cutJob_)
      log("warning", tr("The photo-true appearance could not be made: %1").arg(message));
  });
  updateAction();
}

AppearanceController::~AppearanceController() = default;

bool AppearanceController::wanted() const {
  return document_->appearance() == Appearance::Photo && document_->hasPhotos() && !document_->log();
}

bool AppearanceController::isWorking() const {
  return settle_.isActive() || cutSettle_.isActive() || jobs_->isRunning(facesJob_) ||
         jobs_->isRunning(cutJob_);
}

void AppearanceController::updateAction() {
  const QSignalBlocker blocker(photoTrueAction_);
  photoTrueAction_->setEnabled(document_->hasPhotos() && !document_->log());
  photoTrueAction_->setChecked(document_->appearance() == Appearance::Photo);
}

// Anything the surfaces are made of changed: the views show the procedural wood of the new model at once
// (their pictures belong to the old one); the photo-true ones follow once the edits settle.
void AppearanceController::documentChanged() {
  updateAction();
  const bool newModel = !source_ || source_->model != document_->model();
  if (newModel || !wanted()) {  // what runs is for a model no longer shown
    cutSettle_.stop();
    for (int job : {facesJob_, cutJob_})
      if (jobs_->isRunning(job)) jobs_->cancel(job);
    source_.reset();
  }
  if (!wanted()) {
    settle_.stop();
    cuts_.clear();
    faces_->setAppearanceFaces(nullptr, {});
    showCut({});
    return;
  }
  settle_.start();
}

void AppearanceController::showCut(const CutAppearance& cut) {
  cutView_->setCutAppearance(cut);
  viewport_->setCutAppearance(cut);
  if (cut.model) emit cutMade();
}

// The faces (and the photos' guidance when the model is new), then the cut if it is not made yet.
void AppearanceController::startFaces() {
  if (!wanted()) return;
  const auto model = document_->model();
  if (source_ && source_->model == model && faces_->showsAppearanceFaces()) {
    startCut();
    return;
  }
  for (int job : {facesJob_, cutJob_})
    if (jobs_->isRunning(job)) jobs_->cancel(job);
  const auto photos = document_->photos();
  const FaceSet heldOut = document_->project().heldOutFaces;
  const auto known = source_ && source_->model == model ? source_ : nullptr;
  const float pxPerMm = settings_.pxPerMm;
  facesJob_ = jobs_->start(
      tr("Photo-true appearance"),
      [model, photos, heldOut, known, pxPerMm](const Progress& progress,
                                               const JobRunner::Preview& preview) -> QVariant {
        FacesUpdate update{known ? known : makeSource(model, photos, heldOut, progress.part(0.0, 0.15)), {}};
        preview(QVariant::fromValue(update));  // the guidance: the cut can start
        const Block& block = model->block();
        for (FaceId face : kAllFaces) {
          const int i = faceIndex(face);
          update.faces[i] = toQImage(update.source->appearance->renderFace(
              face, block.faceImageSize(face, pxPerMm),
              progress.part(0.15 + 0.85 * i / 6, 0.15 + 0.85 * (i + 1) / 6)));
          preview(QVariant::fromValue(update));
        }
        return QVariant::fromValue(update);
      },
      [this](const QVariant& result) {
        const auto update = result.value<FacesUpdate>();
        faces_->setAppearanceFaces(update.source->model, update.faces);
        emit facesMade();
      },
      [this](const QVariant& preview) {
        const auto update = preview.value<FacesUpdate>();
        const bool first = source_ != update.source;
        source_ = update.source;
        if (std::any_of(update.faces.begin(), update.faces.end(),
                        [](const QImage& f) { return !f.isNull(); }))
          faces_->setAppearanceFaces(update.source->model, update.faces);
        if (first) startCut();
      },
      false);
}

// The cut panel's plane, from the kept cuts or made in the background beside the faces.
void AppearanceController::startCut() {
  if (!wanted() || !source_ || source_->model != document_->model()) return;
  const CutPlaneSetting setting = document_->cutPlane();
  const auto kept = std::find_if(cuts_.begin(), cuts_.end(), [&](const CutAppearance& cut) {
    return cut.model == source_->model && cut.plane == setting;
  });
  if (kept != cuts_.end()) {
    showCut(*kept);
    return;
  }
  try {
    if (!setting.plane().boundsInBlock(source_->model->block())) return;  // the panel says it misses
  } catch (const InputError&) {
    return;
  }
  if (jobs_->isRunning(cutJob_)) jobs_->cancel(cutJob_);
  const auto source = source_;
  cutJob_ = jobs_->start(
      tr("Photo-true cut"),
      [source, setting](const Progress& progress, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(makeCut(*source, setting, progress));
      },
      [this](const QVariant& result) {
        const auto cut = result.value<CutAppearance>();
        cuts_.push_front(cut);
        if (cuts_.size() > kKeptCuts) cuts_.pop_back();
        showCut(cut);
      },
      {}, false);
}

}  // namespace kerf
