// MainWindow: logs and the board cut from them (docs/editor.md, "Logs and boards"): File ▸ Open Log…,
// New Random Log…, Save Log As…, Close Log; the "Log view" dock (widgets/log_view.hpp) and the "Board"
// dock (placement and the knot table). While the document has a log, its faces are the board's faces,
// rendered with the knot model in the background (latest wins), and the 3D view shows them on the board.
#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <cmath>
#include <numbers>

#include "board_controls.hpp"
#include "cut_view.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "field/knot_shape.hpp"
#include "io/log_data_import.hpp"
#include "job_runner.hpp"
#include "knot_table.hpp"
#include "log_board_faces.hpp"
#include "log_view.hpp"
#include "main_window.hpp"
#include "render/board_wood.hpp"
#include "util/error.hpp"
#include "viewport3d.hpp"

namespace kerf {

void MainWindow::createLogDocks() {
  logView_ = new LogView(this);
  auto* logViewDock = new QDockWidget(tr("Log view"), this);
  logViewDock->setObjectName("logViewDock");
  logViewDock->setWidget(logView_);
  addDockWidget(Qt::BottomDockWidgetArea, logViewDock);
  if (auto* cut = findChild<QDockWidget*>("cutDock")) {
    tabifyDockWidget(cut, logViewDock);
    cut->raise();
  }

  boardControls_ = new BoardControls(this);
  knotTable_ = new KnotTable(this);
  auto* boardPane = new QSplitter(Qt::Vertical, this);
  boardPane->addWidget(boardControls_);
  // Below the placement: the knot table, and the choice of a CLT / veneer / plywood panel from the log.
  auto* tabs = new QTabWidget(boardPane);
  tabs->setObjectName("boardTabs");
  tabs->addTab(knotTable_, tr("Knots"));
  boardPane->addWidget(tabs);
  boardPane->setStretchFactor(1, 1);
  createPanelDock(tabs);
  auto* boardDock = new QDockWidget(tr("Board"), this);
  boardDock->setObjectName("boardDock");
  boardDock->setWidget(boardPane);
  addDockWidget(Qt::RightDockWidgetArea, boardDock);
  if (auto* parameters = findChild<QDockWidget*>("parametersDock")) {
    tabifyDockWidget(parameters, boardDock);
    parameters->raise();
  }
  // Shown when a log is opened (or from the View menu): without one the window stays as it was.
  logViewDock->hide();
  boardDock->hide();

  const auto editBoard = [this](const Board& board, bool finished) {
    try {
      document_->editBoard(board, finished);
    } catch (const InputError& e) {
      logMessage("error", QString::fromUtf8(e.what()));
      if (document_->log()) boardControls_->setBoard(document_->log()->board);
    }
  };
  connect(logView_, &LogView::boardEdited, this, editBoard);
  connect(boardControls_, &BoardControls::boardEdited, this, editBoard);
  connect(boardControls_, &BoardControls::defaultBoardRequested, this, [this] {
    if (document_->log()) document_->editBoard(defaultBoard(document_->log()->log), true);
  });
  connect(logView_, &LogView::knotClicked, knotTable_, &KnotTable::setSelectedKnot);
  connect(knotTable_, &KnotTable::knotSelected, logView_, &LogView::setSelectedKnot);
  connect(knotTable_, &KnotTable::knotEdited, this, &MainWindow::editKnot);
  connect(knotTable_, &KnotTable::addRequested, this, &MainWindow::addKnot);
  connect(knotTable_, &KnotTable::deleteRequested, this, &MainWindow::deleteKnot);

  connect(document_, &Document::logChanged, this, &MainWindow::showLog);
  connect(document_, &Document::boardChanged, this, [this] {
    if (!document_->log()) return;
    logView_->setBoard(document_->log()->board);
    boardControls_->setBoard(document_->log()->board);
    updateBoardWood(false);
    renderFaces();
  });
  // Knot parameters and colours (the schema's sliders) change the field.
  connect(document_, &Document::modelChanged, this, [this] {
    if (document_->log()) updateBoardWood(true);
  });
}

void MainWindow::createLogActions(QMenu* file) {
  QAction* open = file->addAction(tr("Open &Log…"), this, &MainWindow::chooseLog);
  open->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
  open->setToolTip(
      tr("Open a tree log (a Kerf .kerflog file, or a Gran_1 folder of CT data) and cut a "
         "board from it"));
  file->addAction(tr("New &Random Log…"), this, [this] {
    bool ok = false;
    const int seed = QInputDialog::getInt(this, tr("New Random Log"),
                                          tr("Seed (each seed gives another spruce-like log):"), 1, 0,
                                          std::numeric_limits<int>::max(), 1, &ok);
    if (ok) openRandomLog(static_cast<std::uint32_t>(seed));
  });
  saveLogAction_ = file->addAction(tr("Save Log &As…"), this, [this] { saveLogAs(); });
  saveLogAction_->setEnabled(false);
  closeLogAction_ = file->addAction(tr("Close Lo&g"), this, &MainWindow::closeLog);
  closeLogAction_->setToolTip(tr("Back to the block's own wood model (undoable)"));
  closeLogAction_->setEnabled(false);
}

void MainWindow::chooseLog() {
  const QString chosen =
      QFileDialog::getOpenFileName(this, tr("Open a Kerf log, or any file of a Gran_1 log folder"),
                                   QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation),
                                   tr("Logs (*.kerflog *.json *.bmp);;Kerf logs (*.kerflog);;All files (*)"));
  if (chosen.isEmpty()) return;
  const QFileInfo info(chosen);
  openLog(info.suffix().compare("kerflog", Qt::CaseInsensitive) == 0 ? chosen : info.absolutePath());
}

void MainWindow::openLog(const QString& path) {
  jobs_->start(
      tr("Opening log %1").arg(QFileInfo(path).fileName()),
      [path](const Progress&, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(std::make_shared<const LogModel>(loadLog(path.toStdString())));
      },
      [this, path](const QVariant& result) {
        attachLog(*result.value<std::shared_ptr<const LogModel>>());
        logMessage("info", tr("Opened log %1").arg(path));
      },
      {}, false);
}

void MainWindow::openRandomLog(std::uint32_t seed) {
  RandomLogOptions options;
  options.seed = seed;
  try {
    attachLog(generateRandomLog(options));
  } catch (const InputError& e) {
    showError(QString::fromUtf8(e.what()));
  }
}

void MainWindow::attachLog(LogModel log) {
  const Board board = defaultBoard(log);
  const QString name = QString::fromStdString(log.name);
  ProjectLog projectLog{std::move(log), board};
  if (!hasDocument_) {  // nothing open yet: the log becomes a new, unsaved document
    Project project;
    project.block = Block(board.size);
    project.log = std::move(projectLog);
    hasDocument_ = true;
    documentReadyPending_ = true;
    document_->reset(project, QString(), name, {});
  } else {
    document_->setLog(std::move(projectLog), tr("Open log %1").arg(name));
  }
  for (const char* name : {"logViewDock", "boardDock"}) {
    if (auto* dock = findChild<QDockWidget*>(name)) {
      dock->show();
      dock->raise();
    }
  }
  emit logOpened();
}

void MainWindow::closeLog() {
  if (document_->log()) document_->setLog(std::nullopt, tr("Close log"));
}

bool MainWindow::saveLogAs(QString path) {
  if (!document_->log()) return false;
  if (path.isEmpty()) {
    path = QFileDialog::getSaveFileName(this, tr("Save Log"),
                                        QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) +
                                            "/" + document_->name() + ".kerflog",
                                        tr("Kerf logs (*.kerflog)"));
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += ".kerflog";
  }
  try {
    saveLogFile(document_->log()->log, path.toStdString());
  } catch (const InputError& e) {
    showError(tr("The log was not saved: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
  logMessage("info", tr("Saved log %1").arg(path));
  statusBar()->showMessage(tr("Saved log %1").arg(QFileInfo(path).fileName()), 4000);
  return true;
}

void MainWindow::showLog() {
  const auto& log = document_->log();
  const bool hadLog = logShown_;
  logShown_ = log.has_value();
  saveLogAction_->setEnabled(log.has_value());
  closeLogAction_->setEnabled(log.has_value());
  if (showPhotosOn3dAction_) showPhotosOn3dAction_->setEnabled(!log);  // the photos are not of the board
  logView_->setLog(log ? std::make_shared<const LogModel>(log->log) : nullptr);
  knotTable_->setKnots(log ? log->log.knots : std::vector<Knot>{});
  knotTable_->setEnabled(log.has_value());
  boardControls_->setEnabled(log.has_value());
  if (log) {
    logView_->setBoard(log->board);
    boardControls_->setBoard(log->board);
    viewport_->setShowPhotos(false);  // the document's photos are not of this board
  } else {                            // the 3D view shows the block's own model again
    viewport_->setShowPhotos(showPhotosOn3dAction_ && showPhotosOn3dAction_->isChecked());
  }
  updateBoardWood(true);
  if (log || hadLog) renderFaces();  // a document without a log renders on modelChanged alone
}

// The board's six faces: a quarter-resolution preview first, then full resolution; a newer edit
// (board moved, knot edited, parameter changed) cancels the running one.
void MainWindow::renderBoardFaces() {
  const ProjectLog log = *document_->log();
  const WoodParameters params = document_->project().params;
  const float pxPerMm = settings_.pxPerMm;
  if (renderJob_ && jobs_->isRunning(renderJob_)) jobs_->cancel(renderJob_);
  const auto show = [this](const QVariant& faces) {
    renderings_ = faces.value<std::array<QImage, 6>>();
    updateFacesView();
  };
  renderJob_ = jobs_->start(
      tr("Rendering board"),
      [log, params, pxPerMm](const Progress& progress, const JobRunner::Preview& preview) -> QVariant {
        preview(QVariant::fromValue(
            renderLogBoardFaces(log, params, pxPerMm / 4.0f, Progress{nullptr, progress.stop})));
        return QVariant::fromValue(renderLogBoardFaces(log, params, pxPerMm, progress));
      },
      [this, show](const QVariant& faces) {
        show(faces);
        emit facesRendered();
        if (documentReadyPending_) {
          documentReadyPending_ = false;
          emit documentReady();
        }
      },
      [this, show](const QVariant& faces) {
        show(faces);
        emit facesPreviewed();
      },
      false);
}

// The knot field (its noise tables take ~35 ms for the 108 knots of the spruce log, docs/performance.md)
// is made in the background after a knot or parameter edit, the views keeping the previous field until
// it is ready (latest wins); the field of another log (another stem) is made at once. A board move reuses
// the field: only the views' knot grid is rebuilt.
void MainWindow::updateBoardWood(bool logOrParameters) {
  if (boardWoodJob_ && jobs_->isRunning(boardWoodJob_)) jobs_->cancel(boardWoodJob_);
  boardWoodJob_ = 0;
  const auto& log = document_->log();
  const auto show = [this](std::shared_ptr<const KnotField> field,
                           std::shared_ptr<const WoodColorMap> colors) {
    auto wood = std::make_shared<BoardWood>();
    wood->field = std::move(field);
    wood->colors = std::move(colors);
    wood->board = document_->log()->board;
    boardWood_ = std::move(wood);
    viewport_->setBoardWood(boardWood_);
    cutView_->setBoardWood(boardWood_);
  };
  if (!log) {
    boardWood_.reset();
    viewport_->setBoardWood(nullptr);
    cutView_->setBoardWood(nullptr);
  } else if (!logOrParameters && boardWood_) {
    show(boardWood_->field, boardWood_->colors);
  } else {
    const LogModel logModel = log->log;
    const WoodParameters params = document_->project().params;
    const auto make = [logModel, params] {
      return std::make_pair(std::make_shared<const KnotField>(logModel, KnotSettings::fromParameters(params)),
                            std::make_shared<const WoodColorMap>(logColorMap(logModel, params)));
    };
    // Another log (opened, or another document): at once, so no view shows the old log's wood.
    const Stem& stem = log->log.stem;
    const bool sameStem = boardWood_ && boardWood_->field->log().stem.heightStep == stem.heightStep &&
                          boardWood_->field->log().stem.pith == stem.pith &&
                          boardWood_->field->log().stem.radii == stem.radii;
    if (!sameStem) {
      const auto [field, colors] = make();
      show(field, colors);
      return;
    }
    show(boardWood_->field, boardWood_->colors);  // the board as it is now; the edited knots follow
    boardWoodJob_ = jobs_->start(
        tr("Knot field"),
        [make](const Progress&, const JobRunner::Preview&) { return QVariant::fromValue(make()); },
        [this, show](const QVariant& result) {
          if (!document_->log()) return;
          const auto made =
              result
                  .value<std::pair<std::shared_ptr<const KnotField>, std::shared_ptr<const WoodColorMap>>>();
          show(made.first, made.second);
        },
        {}, false);
  }
}

void MainWindow::addKnot() {
  if (!document_->log()) return;
  const ProjectLog& log = *document_->log();
  const glm::vec2 pith = log.log.stem.pithAt(log.board.center.z);
  KnotShape shape;
  shape.heightMm = std::clamp(log.board.center.z, 0.0f, log.log.stem.height());
  shape.azimuthRad = std::atan2(log.board.center.y - pith.y, log.board.center.x - pith.x);
  shape.lengthMm = 1.25f * log.log.stem.maxRadius();
  std::vector<Knot> knots = log.log.knots;
  knots.push_back(makeKnot(shape));
  try {
    document_->editKnots(std::move(knots), tr("Add knot"));
    knotTable_->setSelectedKnot(static_cast<int>(document_->log()->log.knots.size()) - 1);
    logView_->setSelectedKnot(knotTable_->selectedKnot());
  } catch (const InputError& e) {
    showError(QString::fromUtf8(e.what()));
  }
}

void MainWindow::deleteKnot(int knot) {
  if (!document_->log() || knot < 0 || knot >= static_cast<int>(document_->log()->log.knots.size())) return;
  std::vector<Knot> knots = document_->log()->log.knots;
  knots.erase(knots.begin() + knot);
  document_->editKnots(std::move(knots), tr("Delete knot %1").arg(knot + 1));
}

void MainWindow::editKnot(int knot, const KnotShape& shape) {
  if (!document_->log() || knot < 0 || knot >= static_cast<int>(document_->log()->log.knots.size())) return;
  std::vector<Knot> knots = document_->log()->log.knots;
  knots[knot] = makeKnot(shape, knots[knot].distanceStep, knots[knot].endDistance);
  try {
    document_->editKnots(std::move(knots), tr("Edit knot %1").arg(knot + 1));
  } catch (const InputError& e) {
    logMessage("error", QString::fromUtf8(e.what()));
    knotTable_->setKnots(document_->log()->log.knots);  // back to what is valid
  }
}

}  // namespace kerf
