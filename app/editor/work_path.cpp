#include "work_path.hpp"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLayout>
#include <QMenu>
#include <QMenuBar>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolBar>
#include <cmath>

#include "document.hpp"
#include "document_jobs.hpp"
#include "faces_view.hpp"
#include "field/ring_uncertainty.hpp"
#include "fit_quality.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"
#include "recent_files.hpp"
#include "start_page.hpp"
#include "texture_controller.hpp"
#include "window_layout.hpp"

namespace kerf {
namespace {

QString stageName(ReconstructStage stage) {
  switch (stage) {
    case ReconstructStage::Rings:
      return WorkPath::tr("Reconstruct 1/3: finding the rings");
    case ReconstructStage::Field:
      return WorkPath::tr("Reconstruct 2/3: fitting how the tree grew");
    case ReconstructStage::Appearance:
      return WorkPath::tr("Reconstruct 3/3: matching pores, rays and colours");
  }
  return {};
}

}  // namespace

WorkPath::WorkPath(MainWindow* window, QStackedWidget* facesStack)
    : QObject(window), window_(window), facesStack_(facesStack) {
  startPage_ = new StartPage(window_->files()->recentFiles(), facesStack_);
  facesStack_->insertWidget(0, startPage_);
  facesStack_->setCurrentWidget(startPage_);
  connect(startPage_, &StartPage::openPhotosRequested, this, [this] { openPhotos(); });
  connect(startPage_, &StartPage::openProjectRequested, window_->files(), &FilesController::chooseDocument);
  connect(startPage_, &StartPage::demoRequested, window_, [this] { window_->openDemo(defaultDemoFolder()); });
  connect(startPage_, &StartPage::recentRequested, window_->files(), &FilesController::openDocument);

  openPhotosAction_ = new QAction(tr("Open &Photos…"), this);
  openPhotosAction_->setToolTip(
      tr("Open a folder of photos of the block's faces (A_col.png .. F_col.png); the 3D block shows them "
         "until the wood is reconstructed"));
  connect(openPhotosAction_, &QAction::triggered, this, [this] {
    if (window_->files()->maybeSave()) openPhotos();
  });
  reconstructAction_ = new QAction(tr("&Reconstruct"), this);
  reconstructAction_->setObjectName(QStringLiteral("reconstructAction"));
  reconstructAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
  reconstructAction_->setToolTip(
      tr("From the photos to the wood inside the block, in one go (Ctrl+R): find the annual rings on each "
         "face, work out how the tree grew through the block (where the pith runs, how the rings bend), "
         "then match the pores, rays and colours to the photos, and show a cut. Runs in the background; "
         "press again to stop (what has been found stays; Ctrl+Z undoes each step)"));
  connect(reconstructAction_, &QAction::triggered, this, &WorkPath::reconstruct);

  if (auto* file = window_->findChild<QMenu*>(QStringLiteral("fileMenu"))) {
    QAction* before = file->actions().value(1);  // after Open Demo Block, before Open Project
    file->insertAction(before, openPhotosAction_);
  }
  if (auto* rings = window_->findChild<QMenu*>(QStringLiteral("ringsMenu"))) {
    QAction* first = rings->actions().value(0);
    rings->insertAction(first, reconstructAction_);
    rings->insertSeparator(first);
  }
  // The work's own tool bar, in the menu bar's corner: it takes no height from the wood.
  toolBar_ = new QToolBar(tr("Work"), window_);
  toolBar_->setObjectName(QStringLiteral("workToolBar"));
  toolBar_->setToolButtonStyle(Qt::ToolButtonTextOnly);
  toolBar_->addAction(openPhotosAction_);
  toolBar_->addAction(reconstructAction_);
  // As high as the menus: the menu bar must not grow.
  toolBar_->setContentsMargins(0, 0, 0, 0);
  toolBar_->layout()->setContentsMargins(0, 0, 0, 0);
  toolBar_->setStyleSheet(
      QStringLiteral("QToolBar { border: 0; padding: 0; spacing: 2px; } "
                     "QToolButton { padding: 0 6px; }"));
  toolBar_->setMaximumHeight(window_->menuBar()->sizeHint().height());
  window_->menuBar()->setCornerWidget(toolBar_, Qt::TopRightCorner);

  fitLabel_ = new QLabel(window_);
  fitLabel_->setObjectName(QStringLiteral("fitQuality"));
  window_->statusBar()->addPermanentWidget(fitLabel_);

  Document* document = window_->document();
  connect(window_, &MainWindow::documentOpened, this, &WorkPath::documentOpened);
  connect(document, &Document::documentReset, this, [this] {
    facesStack_->setCurrentIndex(1);  // the faces
    updateFitLabel();
    updateActions();
  });
  connect(document, &Document::photosChanged, this, &WorkPath::updateActions);
  connect(window_, &MainWindow::photosImported, this, [this] { showPhotosOnBlock(true); });
  connect(window_, &MainWindow::growthFieldFitted, this, [this] {
    showPhotosOnBlock(false);
    updateFitLabel();
    annotationsChangedSinceFit_ = false;
  });
  connect(document, &Document::annotationsChanged, this, &WorkPath::annotationsEdited);
  connect(document, &Document::documentReset, this, [this] {
    annotationsChangedSinceFit_ = true;
    appearanceField_.reset();
  });
  connect(window_->texture(), &TextureController::textureInferred, this, [this] {
    const Project& project = window_->document()->project();
    appearanceField_ = fieldFingerprint(project.params, project.effectiveRates(), project.knots);
  });
  // How sure the fit is lands later, and an undo or redo hides or shows it again.
  connect(document, &Document::ringUncertaintyChanged, this, &WorkPath::updateFitLabel);
  connect(document, &Document::modelChanged, this, [this] {
    if (!isRunning()) updateFitLabel();
  });
  connect(window_->showPhotosOn3dAction(), &QAction::triggered, this, [this] { photosOnBlockByUs_ = false; });
  connect(window_->jobs(), &JobRunner::jobFailed, this, &WorkPath::ended);
  connect(window_->jobs(), &JobRunner::jobProgress, this, [this](int id, double fraction) {
    if (id == job_) showStage(fraction);
  });
  connect(window_->jobs(), &JobRunner::jobCancelled, this, [this](int id) { ended(id, {}); });
  updateActions();
}

bool WorkPath::showingStartPage() const {
  return facesStack_->currentWidget() == startPage_;
}

bool WorkPath::isRunning() const {
  return job_ && window_->jobs()->isRunning(job_);
}

void WorkPath::openPhotos(QString folder) {
  if (folder.isEmpty()) {
    folder = QFileDialog::getExistingDirectory(
        window_, tr("A folder with a photo of each face (A_col.png .. F_col.png)"),
        QStandardPaths::writableLocation(QStandardPaths::PicturesLocation));
    if (folder.isEmpty()) return;
  }
  window_->openDocument(folder);
}

// A folder of photos has no wood fitted to it yet: the block shows the photos rather than a made-up wood.
void WorkPath::documentOpened(const QString& path) {
  const Document* document = window_->document();
  const bool photosWithoutModel =
      QFileInfo(path).isDir() && document->hasPhotos() && !document->project().rates && !document->log();
  photosOnBlockByUs_ = false;
  window_->showPhotosOn3dAction()->setChecked(photosWithoutModel);
  photosOnBlockByUs_ = photosWithoutModel;
}

void WorkPath::showPhotosOnBlock(bool on) {
  if (on) {
    if (!window_->showPhotosOn3dAction()->isChecked()) photosOnBlockByUs_ = true;
    window_->showPhotosOn3dAction()->setChecked(true);
  } else if (photosOnBlockByUs_) {
    window_->showPhotosOn3dAction()->setChecked(false);
    photosOnBlockByUs_ = false;
  }
}

void WorkPath::updateActions() {
  const Document* document = window_->document();
  const bool running = isRunning();
  reconstructAction_->setEnabled(running ||
                                 (window_->hasDocument() && document->hasPhotos() && !document->log()));
  const QString text = running ? tr("Stop &Reconstruct") : tr("&Reconstruct");
  if (reconstructAction_->text() == text) return;
  reconstructAction_->setText(text);
  // The menu bar places its corner by the size it had: place it again for the new text.
  toolBar_->adjustSize();
  window_->menuBar()->setCornerWidget(toolBar_, Qt::TopRightCorner);
}

// While Reconstruct runs, its stage and progress take the fit's place in the status bar (the job status
// beside it shows the newest job, often a quick render of a preview).
void WorkPath::showStage(double fraction) {
  fitLabel_->setText(tr("%1 — %2 %").arg(stage_).arg(std::lround(100 * fraction)));
  fitLabel_->setToolTip(tr("Ctrl+R or the Stop Reconstruct button stops it; what has been found stays"));
}

void WorkPath::updateFitLabel() {
  const auto fit = window_->rings()->lastFit();
  if (!fit || !window_->document()->project().rates) {
    fitLabel_->clear();
    fitLabel_->setToolTip({});
    return;
  }
  std::optional<FitSureness> sure;
  if (const RingUncertainty* u = window_->document()->ringUncertainty())
    sure = FitSureness{u->quantile(0.5), u->quantile(0.9)};
  fitLabel_->setText(summarizeFit(fit->lossRings, fit->ambiguous, sure));
  fitLabel_->setToolTip(explainFit(fit->lossRings, fit->ambiguous, sure));
}

void WorkPath::cancel() {
  if (isRunning()) window_->jobs()->cancel(job_);
}

void WorkPath::reconstruct() {
  if (isRunning()) {
    cancel();
    return;
  }
  Document* document = window_->document();
  const auto refuse = [this](const QString& message) {
    window_->showError(message);
    emit reconstructFailed(message);
  };
  if (!window_->hasDocument() || !document->hasPhotos() || document->log()) {
    refuse(
        tr("Reconstruct needs photos of the block's faces: File ▸ Open Photos (a folder of A_col.png .. "
           "F_col.png), or File ▸ Import Photos."));
    return;
  }
  JobRunner* jobs = window_->jobs();
  if (window_->rings()->isBusy() || window_->texture()->isRunning()) {
    refuse(tr("Other ring or texture work is still running; reconstruct when it has finished."));
    return;
  }
  window_->rings()->cancelUncertainty();  // of the field this run may replace; estimated again at the end
  ReconstructInput input;
  const Project& project = document->project();
  input.block = project.block;
  input.params = project.params;
  input.photos = document->photos();
  input.heldOut = project.heldOutFaces;
  input.annotations = project.annotations;
  input.appearance = window_->texture()->textureOptions();
  // The photo-true appearance shows the photos themselves: the procedural texture would not be seen, so its
  // minute of inference is skipped (Texture ▸ Infer Texture from Photos still runs it).
  const bool photoTrue = document->appearance() == Appearance::Photo;
  const bool infer = inferAppearance_ && !photoTrue;
  if (inferAppearance_ && photoTrue)
    window_->logMessage("info", tr("The appearance is photo-true: Reconstruct fits the field and makes the "
                                   "surfaces of the photos; the procedural texture is not inferred"));
  input.inferAppearance = infer;
  input.detector = window_->rings()->detector();
  // After a correction only what depends on it runs again; with nothing changed, all of it (the user asked).
  ReconstructPlan plan = planReconstruct(currentState(), infer);
  if (plan.nothing()) {
    plan = ReconstructPlan{};
    plan.infer = infer;
    window_->logMessage("info",
                        tr("Nothing changed since the wood was reconstructed: reconstructing it all again"));
  } else if (!plan.detect) {
    input.rings = window_->rings()->ringDetection();
    if (!plan.fit) input.field = window_->rings()->lastFit();
    input.inferAppearance = plan.infer;
    window_->logMessage(
        "info", !plan.fit
                    ? tr("Reconstructing: the rings and the field are as they were; inferring the wood again")
                    : tr("Reconstructing: the rings are kept as they are (your corrections with them); "
                         "refitting the field%1")
                          .arg(plan.infer ? tr(" and the wood") : QString()));
  }
  if (plan.detect) window_->logMessage("info", tr("Reconstructing the wood from the face photos"));
  job_ = jobs->start(
      stageName(plan.detect ? ReconstructStage::Rings
                : plan.fit  ? ReconstructStage::Field
                            : ReconstructStage::Appearance),
      [input](const Progress& progress, const JobRunner::Preview& preview) -> QVariant {
        reconstructFromPhotos(input, progress, [&preview](const ReconstructEvent& event) {
          preview(QVariant::fromValue(std::make_shared<const ReconstructEvent>(event)));
        });
        return true;
      },
      [this](const QVariant&) { finish(); },
      [this](const QVariant& event) {
        if (const auto e = event.value<std::shared_ptr<const ReconstructEvent>>()) onEvent(*e);
      },
      false);
  updateActions();
}

void WorkPath::onEvent(const ReconstructEvent& event) {
  if (event.started) {
    stage_ = stageName(event.stage);
    window_->jobs()->setJobName(job_, stage_);
    showStage(window_->jobs()->progressOf(job_));
    emit stageStarted(event.stage);
    return;
  }
  if (event.rings) {  // the rings over the faces' photos
    applyingDetection_ = true;
    window_->rings()->showRingDetection(event.rings);
    applyingDetection_ = false;
    emit stageLanded(ReconstructStage::Rings);
  } else if (event.fieldPreview) {  // the field as it is being fitted: on the block and the cut
    showPhotosOnBlock(false);
    window_->rings()->showFitPreview(event.fieldPreview->first, event.fieldPreview->second);
  } else if (event.field) {
    if (!window_->rings()->applyFit(event.field)) {
      cancel();
      return;
    }
    // The faces compare photo and model, unless the user chose what they show.
    // It stays so until the user, or the next document, changes it.
    if (!window_->faces()->displayChosenByUser())
      window_->faces()->chooseDisplay(static_cast<int>(FaceDisplay::Split));
    emit stageLanded(ReconstructStage::Field);
  } else if (event.appearancePreview) {
    window_->texture()->showTexturePreview(*event.appearancePreview);
  } else if (event.appearance) {
    if (!window_->texture()->applyTexture(event.appearance)) {
      cancel();
      return;
    }
    emit stageLanded(ReconstructStage::Appearance);
  }
}

// Everything has landed: the cut, at true scale, is where the work ends.
void WorkPath::finish() {
  job_ = 0;
  updateFitLabel();
  window_->rings()->estimateUncertainty();  // now that the appearance no longer needs the cores
  Document* document = window_->document();
  if (!document->cutEnabled()) document->setCutEnabled(true);
  window_->windowLayout()->showDock(QStringLiteral("cutDock"));
  window_->logMessage("info", tr("Reconstructed: the cut shows the wood inside the block; drag the plane in "
                                 "the 3D view or set it beside the cut"));
  updateActions();
  emit reconstructed();
}

void WorkPath::ended(int id, const QString& message) {
  if (id != job_) return;
  job_ = 0;
  updateFitLabel();
  window_->faces()
      ->showDocumentModel();  // back from a preview to the document's wood (what had landed stays)
  updateActions();
  if (!message.isEmpty()) window_->showError(tr("Reconstruct stopped: %1").arg(message));
  emit reconstructFailed(message.isEmpty() ? tr("cancelled") : message);
}

}  // namespace kerf
