#include "cut_photo_controller.hpp"

#include <QAction>
#include <QActionGroup>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QPointer>
#include <QStandardPaths>
#include <QTimer>
#include <QtConcurrent>
#include <functional>

#include "appearance/surface_grid.hpp"
#include "background_pool.hpp"
#include "cut_photo_dialog.hpp"
#include "document.hpp"
#include "face_difference.hpp"
#include "io/cut_photo.hpp"
#include "io/image.hpp"
#include "job_runner.hpp"
#include "qt_image.hpp"
#include "render/board_wood.hpp"
#include "render/renderers.hpp"
#include "util/error.hpp"

namespace kerf {

namespace {

// The longer side of the rectified photo: finer than the panel shows a cut at most zooms, and cheap to
// compare with a CPU rendering of the model.
constexpr int kMaxPictureSide = 1024;

// A photo's pixels, or the reason there are none (a QString).
QVariant readPhoto(const QString& path) {
  try {
    if (!QFileInfo::exists(path)) return QObject::tr("the file does not exist");
    return toQImage(readImage(path.toStdString()));
  } catch (const std::exception& e) {
    return QString::fromUtf8(e.what());
  }
}

bool isError(const QVariant& value) {
  return value.metaType() == QMetaType::fromType<QString>();
}

// Runs `work` on the background pool and hands its result to `done` on the GUI thread, unless `owner` is
// gone by then.
void runInBackground(QObject* owner, std::function<QVariant()> work,
                     std::function<void(const QVariant&)> done) {
  auto* watcher = new QFutureWatcher<QVariant>(owner);
  QObject::connect(watcher, &QFutureWatcher<QVariant>::finished, owner, [watcher, done] {
    done(watcher->result());
    watcher->deleteLater();
  });
  watcher->setFuture(QtConcurrent::run(backgroundPool(), [work] {
    try {
      return work();
    } catch (const std::exception& e) {
      return QVariant(QString::fromUtf8(e.what()));
    }
  }));
}

}  // namespace

CutPhotoController::CutPhotoController(const EditorContext& context, CutView* cutView)
    : EditorController(context),
      cutView_(cutView),
      loadAction_(new QAction(tr("Load &Cut Photo…"), this)),
      alignAction_(new QAction(tr("&Align Cut Photo…"), this)),
      removeAction_(new QAction(tr("Remove Cut P&hoto"), this)),
      displayGroup_(new QActionGroup(this)) {
  loadAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
  loadAction_->setToolTip(
      tr("Lay a photo of the board you sawed on this cut, to compare the real cut surface with the wood Kerf "
         "predicts there: the rings, the colour, the figure (Ctrl+Shift+C). Saw on the plane shown, "
         "photograph the sawn face square on, then align the photo's corners to the cut"));
  alignAction_->setToolTip(
      tr("Fit the cut photo to the cut: drag its four corners onto the corners of the sawn face, turn it by "
         "quarter turns or mirror it (a photo of the other half of the board)"));
  removeAction_->setToolTip(tr("Take the cut photo off the cut (undoable)"));
  // The Cut panel's buttons are narrow: short names there, the full ones in the menus.
  alignAction_->setIconText(tr("Align…"));
  removeAction_->setIconText(tr("Remove"));
  connect(loadAction_, &QAction::triggered, this, &CutPhotoController::chooseCutPhoto);
  connect(alignAction_, &QAction::triggered, this, &CutPhotoController::chooseAlignment);
  connect(removeAction_, &QAction::triggered, this, &CutPhotoController::removeCutPhoto);

  const QString names[] = {tr("Model"), tr("Photo"), tr("Split"), tr("Difference")};
  const QString tips[] = {
      tr("The cut panel shows the model's wood on the cut (Alt+1)"),
      tr("The cut panel shows the photo of the real cut, aligned to the cut (Alt+2)"),
      tr("Compare: the photo of the real cut left of a line, the model's wood right of it; drag the line to "
         "see whether the rings run on across it (Alt+3)"),
      tr("Compare: where the model's wood departs from the photo of the cut, as a heat map: black where they "
         "agree, orange where the model is lighter than the sawn wood, blue where it is darker (Alt+4)")};
  static_assert(std::size(names) == kCutDisplayCount);
  for (int i = 0; i < kCutDisplayCount; ++i) {
    auto* action = new QAction(names[i], displayGroup_);
    action->setCheckable(true);
    action->setChecked(i == 0);
    action->setToolTip(tips[i]);
    action->setShortcut(QKeySequence(Qt::ALT | Qt::Key(Qt::Key_1 + i)));
    connect(action, &QAction::triggered, this, [this, i] { setDisplay(static_cast<CutDisplay>(i)); });
  }

  connect(document_, &Document::cutPhotoChanged, this, &CutPhotoController::photoChanged);
  connect(document_, &Document::blockChanged, this, &CutPhotoController::photoChanged);
  // The model's side: a deferred call, so the cut panel has taken the new model or plane first.
  for (auto signal : {&Document::modelChanged, &Document::cutPlaneChanged, &Document::logChanged})
    connect(document_, signal, this, &CutPhotoController::modelSideChanged);
  connect(cutView_, &CutView::boardWoodChanged, this, &CutPhotoController::modelSideChanged);
  updateActions();
}

void CutPhotoController::chooseCutPhoto() {
  const QString chosen = QFileDialog::getOpenFileName(
      window_, tr("A photo of the sawn cut"),
      QStandardPaths::writableLocation(QStandardPaths::PicturesLocation),
      tr("Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.webp);;All files (*)"));
  if (!chosen.isEmpty()) loadCutPhoto(chosen);
}

void CutPhotoController::loadCutPhoto(const QString& path) {
  const QString file = QFileInfo(path).absoluteFilePath();
  jobs_->start(
      tr("Loading cut photo %1").arg(QFileInfo(path).fileName()),
      [file](const Progress&, const JobRunner::Preview&) { return readPhoto(file); },
      [this, file](const QVariant& result) {
        const QString name = QFileInfo(file).fileName();
        if (isError(result)) {
          showError(tr("Cut photo %1 was not loaded: %2").arg(name, result.toString()));
          return;
        }
        const QImage image = result.value<QImage>();
        CutPhoto photo;
        photo.setup.source = file.toStdString();
        photo.setup.corners = wholePhotoCorners({image.width(), image.height()});
        photo.plane = document_->cutPlane();
        if (!photo.plane.plane().boundsInBlock(document_->project().block)) {
          showError(tr("Cut photo %1 was not loaded: the cut plane misses the block; move it into the block "
                       "first")
                        .arg(name));
          return;
        }
        document_->setCutPhoto(photo, image, tr("Load cut photo %1").arg(name));
        setDisplay(CutDisplay::Split);
        log("info", tr("Cut photo %1 laid on the cut; Cut ▸ Align Cut Photo fits its corners").arg(name));
      },
      {}, false);
}

void CutPhotoController::chooseAlignment() {
  const auto& photo = document_->cutPhoto();
  if (!photo || document_->cutPhotoImage().isNull()) return;
  auto* dialog = new CutPhotoDialog(document_->cutPhotoImage(), photo->setup, window_);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    const FacePhotoSetup& s = dialog->setup();
    try {
      setAlignment(s.corners, s.rotationDegrees, s.flip);
    } catch (const InputError& e) {
      showError(tr("The cut photo was not aligned: %1").arg(QString::fromUtf8(e.what())));
    }
  });
  dialog->open();  // window-modal, returns at once
}

void CutPhotoController::setAlignment(const std::array<glm::vec2, 4>& corners, int rotationDegrees,
                                      bool flip) {
  const auto& current = document_->cutPhoto();
  if (!current) return;
  const QImage& image = document_->cutPhotoImage();
  if (!image.isNull()) validateCorners(corners, {image.width(), image.height()});
  CutPhoto aligned = *current;
  aligned.setup.corners = corners;
  aligned.setup.rotationDegrees = normalizedRotation(rotationDegrees);
  aligned.setup.flip = flip;
  if (aligned == *current) return;
  document_->setCutPhoto(aligned, image, tr("Align cut photo"));
}

void CutPhotoController::removeCutPhoto() {
  if (!document_->cutPhoto()) return;
  document_->setCutPhoto(std::nullopt, {}, tr("Remove cut photo"));
}

void CutPhotoController::setDisplay(CutDisplay display) {
  displayGroup_->actions()[static_cast<int>(display)]->setChecked(true);
  cutView_->setCutDisplay(display);
  startDifference();
}

bool CutPhotoController::showsDocumentPhoto() const {
  return shownPhoto_ && document_->cutPhoto() && *shownPhoto_ == *document_->cutPhoto();
}

void CutPhotoController::updateActions() {
  const bool has = document_->cutPhoto().has_value();
  alignAction_->setEnabled(has && !document_->cutPhotoImage().isNull());
  removeAction_->setEnabled(has);
  for (int i = 1; i < kCutDisplayCount; ++i) displayGroup_->actions()[i]->setEnabled(has);
}

// --- The photo on the cut -----------------------------------------------------------------------------

void CutPhotoController::photoChanged() {
  updateActions();
  const auto& photo = document_->cutPhoto();
  if (!photo) {
    ++rectifyGeneration_;
    restoring_.clear();
    shownPhoto_.reset();
    cutView_->setCutPhoto({});
    emit cutPhotoShown();
    return;
  }
  if (document_->cutPhotoImage().isNull()) {
    restoreImage();
    return;
  }
  startRectify();
}

void CutPhotoController::restoreImage() {
  const QString path = QString::fromStdString(document_->cutPhoto()->setup.source.string());
  if (restoring_ == path) return;
  restoring_ = path;
  ++rectifyGeneration_;
  shownPhoto_.reset();
  cutView_->setCutPhoto({});
  runInBackground(
      this, [path] { return readPhoto(path); },
      [this, path](const QVariant& result) {
        restoring_.clear();
        const auto& photo = document_->cutPhoto();
        if (!photo || QString::fromStdString(photo->setup.source.string()) != path ||
            !document_->cutPhotoImage().isNull())
          return;  // replaced meanwhile
        if (isError(result)) {
          showError(tr("The project's cut photo %1 could not be read: %2. It stays in the project; Load Cut "
                       "Photo… puts another on the cut")
                        .arg(QFileInfo(path).fileName(), result.toString()));
          return;
        }
        document_->restoreCutPhotoImage(result.value<QImage>());
      });
}

void CutPhotoController::startRectify() {
  const int generation = ++rectifyGeneration_;
  const CutPhoto photo = *document_->cutPhoto();
  const QImage image = document_->cutPhotoImage();
  const Block block = document_->project().block;
  struct Rectified {
    SurfaceImage surface;
    float pxPerMm;
  };
  runInBackground(
      this,
      [photo, image, block] {
        const float pxPerMm = cutPhotoPxPerMm(photo, {image.width(), image.height()}, block, kMaxPictureSide);
        const Image rectified = rectifyCutPhoto(fromQImage(image), photo, block, pxPerMm);
        auto result = std::make_shared<Rectified>(
            Rectified{{toQImage(rectified), cutGrid(block, photo.plane.plane(), pxPerMm)}, pxPerMm});
        return QVariant::fromValue(std::shared_ptr<const void>(result));
      },
      [this, generation, photo](const QVariant& result) {
        if (generation != rectifyGeneration_) return;
        if (isError(result)) {
          showError(
              tr("The cut photo %1 could not be laid on the cut: %2")
                  .arg(QString::fromStdString(photo.setup.source.filename().string()), result.toString()));
          return;
        }
        const auto* rectified =
            static_cast<const Rectified*>(result.value<std::shared_ptr<const void>>().get());
        pxPerMm_ = rectified->pxPerMm;
        shownPhoto_ = photo;
        CutPhotoPicture picture;
        picture.photo = rectified->surface;
        picture.plane = photo.plane;
        cutView_->setCutPhoto(picture);
        emit cutPhotoShown();
        startDifference();
      });
}

// --- The difference -------------------------------------------------------------------------------------

void CutPhotoController::modelSideChanged() {
  QTimer::singleShot(0, this, &CutPhotoController::startDifference);
}

void CutPhotoController::startDifference() {
  const CutPhotoPicture& picture = cutView_->cutPhoto();
  if (cutView_->cutDisplay() != CutDisplay::Difference || picture.photo.image.isNull() ||
      cutView_->cutPhotoStale() || !cutView_->model() || cutView_->differenceUpToDate())
    return;
  const int generation = ++differenceGeneration_;
  const std::shared_ptr<const WoodModel> model = cutView_->model();
  // Log mode: the board's wood (the picture the panel draws in GLSL, on the CPU), never photo-true.
  const std::shared_ptr<const BoardWood> board = cutView_->boardWood();
  const QImage appearance = board ? QImage() : cutView_->shownCutAppearance();
  const QImage photo = picture.photo.image;
  const CutPlaneSetting plane = picture.plane;
  const float pxPerMm = pxPerMm_;
  runInBackground(
      this,
      [model, board, appearance, photo, plane, pxPerMm]() -> QVariant {
        // The photo-true cut covers the same rectangle (cutGrid) at its own resolution; the heat map
        // resamples it onto the photo's pixels. The board's cut has renderCut's layout.
        const QImage wood = board                 ? toQImage(renderBoardCut(*board, plane.plane(), pxPerMm))
                            : appearance.isNull() ? toQImage(renderCut(*model, plane.plane(), pxPerMm))
                                                  : appearance;
        return differenceHeatMap(photo, wood);
      },
      [this, generation, model, board, appearance, photo](const QVariant& result) {
        if (generation != differenceGeneration_) return;
        // Another photo was laid on the cut meanwhile (its own start may have been skipped while the
        // panel showed something else): this heat map is of the old one.
        if (cutView_->cutPhoto().photo.image.cacheKey() != photo.cacheKey()) {
          startDifference();
          return;
        }
        if (isError(result)) {
          log("warning", tr("The cut photo could not be compared with the model: %1").arg(result.toString()));
          return;
        }
        CutPhotoPicture picture = cutView_->cutPhoto();
        picture.difference = result.value<QImage>();
        picture.differenceModel = model;
        picture.differenceBoard = board;
        picture.differenceOfAppearance = !appearance.isNull();
        picture.differencePhoto = photo.cacheKey();
        cutView_->setCutPhoto(picture);
        emit differenceReady();
        startDifference();  // the model or the appearance may have changed meanwhile
      });
}

}  // namespace kerf
