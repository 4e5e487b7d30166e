#include "main_window.hpp"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoView>
#include <QVBoxLayout>
#include <iterator>

#include "annotation_layer.hpp"
#include "autosave.hpp"
#include "cut_plane_controls.hpp"
#include "cut_view.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "io/image.hpp"
#include "job_runner.hpp"
#include "job_status_widget.hpp"
#include "log_panel.hpp"
#include "parameter_panel.hpp"
#include "params/builtin_presets.hpp"
#include "util/error.hpp"
#include "viewport3d.hpp"
#include "window_layout.hpp"
#include "work_path.hpp"

namespace kerf {

MainWindow::MainWindow(RenderSettings settings, QWidget* parent) : QMainWindow(parent) {
  document_ = new Document(this);
  jobs_ = new JobRunner(this);
  createViews();
  createDocks();
  layout_ = new WindowLayout(this, centralSplitter_);
  createControllers(settings);  // main_window_controllers.cpp
  createMenus();
  workPath_ = new WorkPath(this, facesStack_);
  connectDocument();

  auto* status = new JobStatusWidget(jobs_, this);
  documentLabel_ = new QLabel(this);
  cursorLabel_ = new QLabel(this);
  cursorLabel_->setMinimumWidth(220);  // room for the fit in words beside it (1366 px)
  statusBar()->addWidget(documentLabel_, 1);
  statusBar()->addPermanentWidget(cursorLabel_);
  statusBar()->addPermanentWidget(status);
  connect(jobs_, &JobRunner::message, this, &MainWindow::logMessage);

  setAcceptDrops(true);
  layout_->restore();
  layout_->addDockButtons(statusBar());
  updateTitle();
}

MainWindow::~MainWindow() {
  jobs_->cancelAll();
  jobs_->waitForDone();
  // The document is deleted with the children, after this destructor; its last signals (the undo stack
  // turning clean) must not reach this window or its controllers by then (UBSan: vptr).
  document_->disconnect();
  layout_->save();
}

void MainWindow::createViews() {
  facesView_ = new FacesView(this);
  facesView_->setPlaceholderText(tr("Opening…"));
  viewport_ = new Viewport3D(this);

  // Above the faces: what they show, how much of the model is blended over the photos, where the
  // photo | model line of Split lies.
  auto* facesPane = new QWidget(this);
  auto* facesBar = new QToolBar(facesPane);
  facesBar->setIconSize(QSize(16, 16));
  displayGroup_ = new QActionGroup(this);
  const QString names[] = {tr("Photos"), tr("Model"), tr("Blend"), tr("Split"), tr("Difference")};
  const QString tips[] = {
      tr("Show the photographs of the faces (Ctrl+1)"),
      tr("Show the model's rendering of the faces (Ctrl+2)"),
      tr("Show the model over the photos; the slider sets how much (Ctrl+3)"),
      tr("Compare: each face's photo left of a line, the model's wood right of it; drag the line (or the "
         "slider) across the faces to see where the rings and the colour part (Ctrl+4)"),
      tr("Compare: where the model's wood departs from the photo, as a heat map: black where they agree, "
         "orange where the model is lighter than the photo, blue where it is darker (Ctrl+5)")};
  static_assert(std::size(names) == kFaceDisplayCount);
  for (int i = 0; i < kFaceDisplayCount; ++i) {
    QAction* action = facesBar->addAction(names[i]);
    action->setCheckable(true);
    action->setToolTip(tips[i]);
    action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_1 + i)));
    action->setData(i);
    displayGroup_->addAction(action);  // FacesController::setDisplayControls connects them
  }
  blendSlider_ = new QSlider(Qt::Horizontal, facesBar);
  blendSlider_->setRange(0, 100);
  blendSlider_->setValue(50);
  blendSlider_->setMaximumWidth(160);
  facesBar->addWidget(blendSlider_);
  auto* facesLayout = new QVBoxLayout(facesPane);
  facesLayout->setContentsMargins(0, 0, 0, 0);
  facesLayout->setSpacing(0);
  facesLayout->addWidget(facesBar);
  facesLayout->addWidget(createAnnotationBar(facesPane));
  facesLayout->addWidget(facesView_, 1);

  centralSplitter_ = new QSplitter(Qt::Horizontal, this);
  centralSplitter_->setObjectName("centralSplitter");
  facesStack_ = new QStackedWidget(this);
  facesStack_->addWidget(facesPane);
  centralSplitter_->addWidget(facesStack_);
  centralSplitter_->addWidget(viewport_);
  centralSplitter_->setStretchFactor(0, 1);
  centralSplitter_->setStretchFactor(1, 1);
  centralSplitter_->setChildrenCollapsible(false);
  setCentralWidget(centralSplitter_);

  connect(facesView_, &FacesView::cursorPositionChanged, this,
          [this](const QString& t) { cursorLabel_->setText(t); });
  connect(viewport_, &Viewport3D::cutPlaneEdited, this,
          [this](const CutPlaneSetting& s, bool finished) { document_->editCutPlane(s, finished); });
}

QToolBar* MainWindow::createAnnotationBar(QWidget* parent) {
  annotationLayer_ = new AnnotationLayer(facesView_);
  auto* bar = new QToolBar(tr("Ring Tracing"), parent);
  bar->setObjectName("ringTracingBar");
  bar->setIconSize(QSize(16, 16));
  bar->setStyleSheet(QStringLiteral("QToolButton { padding: 1px 3px; }"));  // ten buttons in half a window
  bar->addActions(annotationLayer_->toolActions());
  bar->addSeparator();
  bar->addActions(annotationLayer_->editActions());
  connect(annotationLayer_, &AnnotationLayer::message, this,
          [this](const QString& text) { statusBar()->showMessage(text, 8000); });
  return bar;
}

void MainWindow::createDocks() {
  setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
  parameterPanel_ = new ParameterPanel(this);
  parameterPanel_->setPresets(builtInPresets());
  auto* parameters = new QDockWidget(tr("Parameters"), this);
  parameters->setObjectName("parametersDock");
  parameters->setWidget(parameterPanel_);
  addDockWidget(Qt::RightDockWidgetArea, parameters);
  connect(parameterPanel_, &ParameterPanel::parameterEdited, this,
          [this](int index, std::array<float, 3> value, bool finished) {
            try {
              document_->editParameter(static_cast<std::size_t>(index), value, finished);
            } catch (const InputError& e) {
              logMessage("error", QString::fromUtf8(e.what()));
              parameterPanel_->setParameters(document_->project().params);  // back to what is valid
            }
          });
  connect(parameterPanel_, &ParameterPanel::presetChosen, this, &MainWindow::applyPreset);

  // The cut: numeric controls beside the true-scale cut panel.
  cutView_ = new CutView(this);
  cutControls_ = new CutPlaneControls(this);
  auto* cutPane = new QWidget(this);
  auto* cutLayout = new QHBoxLayout(cutPane);
  cutLayout->setContentsMargins(2, 2, 2, 2);
  // The controls scroll rather than squeeze when the dock is short.
  auto* controlsScroll = new QScrollArea(cutPane);
  controlsScroll->setWidget(cutControls_);
  controlsScroll->setWidgetResizable(true);
  controlsScroll->setFrameShape(QFrame::NoFrame);
  controlsScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  controlsScroll->setMinimumWidth(cutControls_->minimumSizeHint().width() + 16);
  // Under the plane's controls, so the cut keeps its height: the photo of the real cut and how it is
  // compared (filled by createControllers).
  auto* controlsColumn = new QVBoxLayout;
  controlsColumn->setContentsMargins(0, 0, 0, 0);
  controlsColumn->setSpacing(0);
  controlsColumn->addWidget(controlsScroll, 1);
  cutBar_ = new QToolBar(cutPane);
  cutBar_->setObjectName("cutPhotoBar");
  cutDisplayBar_ = new QToolBar(cutPane);
  cutDisplayBar_->setObjectName("cutDisplayBar");
  controlsColumn->addWidget(cutBar_);
  controlsColumn->addWidget(cutDisplayBar_);
  cutLayout->addLayout(controlsColumn);
  cutLayout->addWidget(cutView_, 1);
  auto* cut = new QDockWidget(tr("Cut"), this);
  cut->setObjectName("cutDock");
  // Its title down the left side: the height goes to the cut itself.
  cut->setFeatures(cut->features() | QDockWidget::DockWidgetVerticalTitleBar);
  cut->setWidget(cutPane);
  addDockWidget(Qt::BottomDockWidgetArea, cut);
  connect(cutView_, &CutView::cursorPositionChanged, this,
          [this](const QString& t) { cursorLabel_->setText(t); });
  connect(cutControls_, &CutPlaneControls::settingEdited, this,
          [this](const CutPlaneSetting& s, bool finished) { document_->editCutPlane(s, finished); });
  connect(cutControls_, &CutPlaneControls::cutEnabledChanged, document_, &Document::setCutEnabled);
  connect(cutControls_, &CutPlaneControls::cutSideChanged, this, [this](bool ghost) {
    viewport_->setCutSide(ghost ? Viewport3D::CutSide::Ghost : Viewport3D::CutSide::Hide);
  });

  log_ = new LogPanel(this);
  auto* logDock = new QDockWidget(tr("Log"), this);
  logDock->setObjectName("logDock");
  logDock->setWidget(log_);
  addDockWidget(Qt::BottomDockWidgetArea, logDock);
  connect(log_, &LogPanel::badgeTextChanged, this, [logDock](const QString& badge) {
    logDock->setWindowTitle(badge.isEmpty() ? tr("Log") : tr("Log (%1)").arg(badge));
  });

  history_ = new QUndoView(document_->undoStack(), this);
  history_->setEmptyLabel(tr("<opened>"));
  auto* historyDock = new QDockWidget(tr("History"), this);
  historyDock->setObjectName("historyDock");
  historyDock->setWidget(history_);
  addDockWidget(Qt::BottomDockWidgetArea, historyDock);
  createBlockKnotsDock();
  createLogDocks();  // main_window_docks.cpp; WindowLayout places every dock
}

void MainWindow::connectDocument() {
  connect(document_, &Document::modelChanged, this, [this] {
    parameterPanel_->setParameters(document_->project().params);
    faces_->showDocumentModel();
  });
  connect(document_, &Document::cutPlaneChanged, this, [this] {
    const CutPlaneSetting setting = document_->cutPlane();
    viewport_->setCutPlane(setting);
    viewport_->setCutEnabled(document_->cutEnabled());
    cutView_->setCutPlane(setting);
    cutControls_->setSetting(setting);
    cutControls_->setCutEnabled(document_->cutEnabled());
  });
  connect(document_, &Document::photosChanged, this, [this] {
    facesView_->setPhotos(document_->photos());
    viewport_->setFacePhotos(document_->photos());
    faces_->updateFacesView();
  });
  connect(document_, &Document::documentReset, this, [this] {
    facesView_->setBlock(document_->project().block);
    cutControls_->setBlock(document_->project().block);
    updateTitle();
  });
  connect(document_, &Document::modifiedChanged, this, [this](bool) { updateTitle(); });
  connect(document_, &Document::blockChanged, this, [this] {
    facesView_->setBlock(document_->project().block);
    cutControls_->setBlock(document_->project().block);
  });
}

bool MainWindow::isBusy() const {
  return jobs_->isBusy();
}

QString MainWindow::documentName() const {
  return document_->name();
}

QList<QAction*> MainWindow::faceDisplayActions() const {
  return displayGroup_->actions();
}

void MainWindow::applyPreset(const QString& presetId) {
  const Preset* preset = builtInPreset(presetId.toStdString());
  if (!preset) return;
  try {
    document_->applyParameters(preset->applyTo(document_->project().params),
                               tr("Apply preset %1").arg(QString::fromStdString(preset->name)));
    logMessage("info", tr("Preset %1 applied").arg(QString::fromStdString(preset->name)));
  } catch (const InputError& e) {
    showError(QString::fromUtf8(e.what()));
  }
}

void MainWindow::showError(const QString& message) {
  logMessage("error", message);
  showAlert(message, message);
}

void MainWindow::showAlert(const QString& text, const QString& error) {
  lastError_ = error;
  // open() is window-modal but returns at once: the GUI thread never blocks on the user.
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Kerf"), text, QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

void MainWindow::logMessage(const QString& level, const QString& text) {
  log_->appendMessage(level, text);
  if (level == "error") lastError_ = text;
}

void MainWindow::updateTitle() {
  const QString name = hasDocument() ? document_->name() : tr("No document");
  setWindowTitle(tr("%1[*] — Kerf").arg(name));
  setWindowModified(document_->isModified());
  if (!hasDocument()) {
    documentLabel_->setText(tr("No document"));
    return;
  }
  const glm::vec3 size = document_->project().block.size();
  documentLabel_->setText(
      tr("%1 — block %2 × %3 × %4 mm%5")
          .arg(name)
          .arg(size.x, 0, 'g', 4)
          .arg(size.y, 0, 'g', 4)
          .arg(size.z, 0, 'g', 4)
          .arg(document_->filePath().isEmpty() ? tr(" — not saved to a project file yet") : ""));
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!files_->maybeSave()) {
    event->ignore();
    return;
  }
  files_->autosave()->discardCurrent();  // closed on purpose: nothing to recover
  jobs_->cancelAll();                    // fits, renders and exports stop now; an export leaves no file
  event->accept();
}

}  // namespace kerf
