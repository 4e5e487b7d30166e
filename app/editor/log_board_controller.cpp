// LogBoardController: logs and the board cut from them (docs/editor.md, "Logs and boards"): File ▸ Open Log…,
// New Random Log…, Save Log As…, Close Log; the "Log view" dock (widgets/log_view.hpp) and the "Board"
// dock (placement and the knot table) follow the document. While the document has a log, its faces are the
// board's faces (FacesController), and the 3D view shows them on the board.
#include "log_board_controller.hpp"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QStandardPaths>
#include <QWidget>
#include <cmath>
#include <limits>

#include "board_controls.hpp"
#include "cut_view.hpp"
#include "document.hpp"
#include "faces_controller.hpp"
#include "field/knot_shape.hpp"
#include "io/log_data_import.hpp"
#include "job_runner.hpp"
#include "knot_table.hpp"
#include "log_board_faces.hpp"
#include "log_view.hpp"
#include "panel_controls.hpp"
#include "render/board_wood.hpp"
#include "util/error.hpp"
#include "viewport3d.hpp"

namespace kerf {

LogBoardController::LogBoardController(const EditorContext& context, FacesController* faces,
                                       const Views& views)
    : EditorController(context), faces_(faces), views_(views) {
  const auto editBoard = [this](const Board& board, bool finished) {
    try {
      document_->editBoard(board, finished);
    } catch (const InputError& e) {
      log("error", QString::fromUtf8(e.what()));
      if (document_->log()) views_.boardControls->setBoard(document_->log()->board);
    }
  };
  connect(views_.logView, &LogView::boardEdited, this, editBoard);
  connect(views_.boardControls, &BoardControls::boardEdited, this, editBoard);
  connect(views_.boardControls, &BoardControls::defaultBoardRequested, this, [this] {
    if (document_->log()) document_->editBoard(defaultBoard(document_->log()->log), true);
  });
  connect(views_.logView, &LogView::knotClicked, views_.knotTable, &KnotTable::setSelectedKnot);
  connect(views_.knotTable, &KnotTable::knotSelected, views_.logView, &LogView::setSelectedKnot);
  connect(views_.knotTable, &KnotTable::knotEdited, this, &LogBoardController::editKnot);
  connect(views_.knotTable, &KnotTable::addRequested, this, &LogBoardController::addKnot);
  connect(views_.knotTable, &KnotTable::deleteRequested, this, &LogBoardController::deleteKnot);
  connect(views_.panelControls, &PanelControls::panelRequested, this, &LogBoardController::showPanel);
  connect(jobs_, &JobRunner::jobFailed, this, [this](int id, const QString& message) {
    if (id != panelJob_) return;
    panelJob_ = 0;
    showError(tr("The panel could not be made: %1").arg(message));
  });

  connect(document_, &Document::logChanged, this, &LogBoardController::showLog);
  connect(document_, &Document::boardChanged, this, [this] {
    if (!document_->log()) return;
    views_.logView->setBoard(document_->log()->board);
    views_.boardControls->setBoard(document_->log()->board);
    updateBoardWood(false);
    faces_->renderFaces();
  });
  // Knot parameters and colours (the schema's sliders) change the field.
  connect(document_, &Document::modelChanged, this, [this] {
    if (document_->log()) updateBoardWood(true);
  });
}

void LogBoardController::setActions(const Actions& actions) {
  actions_ = actions;
  connect(actions_.saveLog, &QAction::triggered, this, [this] { saveLogAs(); });
  connect(actions_.closeLog, &QAction::triggered, this, &LogBoardController::closeLog);
}

void LogBoardController::chooseRandomLog() {
  bool ok = false;
  const int seed = QInputDialog::getInt(window_, tr("New Random Log"),
                                        tr("Seed (each seed gives another spruce-like log):"), 1, 0,
                                        std::numeric_limits<int>::max(), 1, &ok);
  if (ok) openRandomLog(static_cast<std::uint32_t>(seed));
}

void LogBoardController::showDock(const char* name) {
  if (auto* dock = window_->findChild<QDockWidget*>(name)) {
    dock->show();
    dock->raise();
  }
}

void LogBoardController::chooseLog() {
  const QString chosen =
      QFileDialog::getOpenFileName(window_, tr("Open a Kerf log, or any file of a Gran_1 log folder"),
                                   QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation),
                                   tr("Logs (*.kerflog *.json *.bmp);;Kerf logs (*.kerflog);;All files (*)"));
  if (chosen.isEmpty()) return;
  const QFileInfo info(chosen);
  openLog(info.suffix().compare("kerflog", Qt::CaseInsensitive) == 0 ? chosen : info.absolutePath());
}

void LogBoardController::openLog(const QString& path) {
  jobs_->start(
      tr("Opening log %1").arg(QFileInfo(path).fileName()),
      [path](const Progress&, const JobRunner::Preview&) -> QVariant {
        return QVariant::fromValue(std::make_shared<const LogModel>(loadLog(path.toStdString())));
      },
      [this, path](const QVariant& result) {
        attachLog(*result.value<std::shared_ptr<const LogModel>>());
        log("info", tr("Opened log %1").arg(path));
      },
      {}, false);
}

void LogBoardController::openRandomLog(std::uint32_t seed) {
  RandomLogOptions options;
  options.seed = seed;
  try {
    attachLog(generateRandomLog(options));
  } catch (const InputError& e) {
    showError(QString::fromUtf8(e.what()));
  }
}

void LogBoardController::attachLog(LogModel log) {
  const Board board = defaultBoard(log);
  const QString name = QString::fromStdString(log.name);
  ProjectLog projectLog{std::move(log), board};
  if (!faces_->hasDocument()) {  // nothing open yet: the log becomes a new, unsaved document
    Project project;
    project.block = Block(board.size);
    project.log = std::move(projectLog);
    faces_->beginDocument(false);
    document_->reset(project, QString(), name, {});
  } else {
    document_->setLog(std::move(projectLog), tr("Open log %1").arg(name));
  }
  for (const char* name : {"logViewDock", "boardDock"}) showDock(name);
  emit logOpened();
}

void LogBoardController::closeLog() {
  if (document_->log()) document_->setLog(std::nullopt, tr("Close log"));
}

bool LogBoardController::saveLogAs(QString path) {
  if (!document_->log()) return false;
  if (path.isEmpty()) {
    path = QFileDialog::getSaveFileName(window_, tr("Save Log"),
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
  log("info", tr("Saved log %1").arg(path));
  emit statusShown(tr("Saved log %1").arg(QFileInfo(path).fileName()), 4000);
  return true;
}

void LogBoardController::showLog() {
  const auto& log = document_->log();
  const bool hadLog = logShown_;
  logShown_ = log.has_value();
  actions_.saveLog->setEnabled(log.has_value());
  actions_.closeLog->setEnabled(log.has_value());
  if (actions_.showPhotosOn3d) actions_.showPhotosOn3d->setEnabled(!log);  // the photos are not of the board
  views_.logView->setLog(log ? std::make_shared<const LogModel>(log->log) : nullptr);
  views_.knotTable->setKnots(log ? log->log.knots : std::vector<Knot>{});
  views_.knotTable->setEnabled(log.has_value());
  views_.boardControls->setEnabled(log.has_value());
  if (log) {
    views_.logView->setBoard(log->board);
    views_.boardControls->setBoard(log->board);
    views_.viewport->setShowPhotos(false);  // the document's photos are not of this board
  } else {                                  // the 3D view shows the block's own model again
    views_.viewport->setShowPhotos(actions_.showPhotosOn3d && actions_.showPhotosOn3d->isChecked());
  }
  updateBoardWood(true);
  if (log || hadLog) faces_->renderFaces();  // a document without a log renders on modelChanged alone
}

// The knot field (its noise tables take ~35 ms for the 108 knots of the spruce log, docs/performance.md)
// is made in the background after a knot or parameter edit, the views keeping the previous field until
// it is ready (latest wins); the field of another log (another stem) is made at once. A board move reuses
// the field: only the views' knot grid is rebuilt.
void LogBoardController::updateBoardWood(bool logOrParameters) {
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
    views_.viewport->setBoardWood(boardWood_);
    views_.cutView->setBoardWood(boardWood_);
  };
  if (!log) {
    boardWood_.reset();
    views_.viewport->setBoardWood(nullptr);
    views_.cutView->setBoardWood(nullptr);
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

void LogBoardController::addKnot() {
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
    views_.knotTable->setSelectedKnot(static_cast<int>(document_->log()->log.knots.size()) - 1);
    views_.logView->setSelectedKnot(views_.knotTable->selectedKnot());
  } catch (const InputError& e) {
    showError(QString::fromUtf8(e.what()));
  }
}

void LogBoardController::deleteKnot(int knot) {
  if (!document_->log() || knot < 0 || knot >= static_cast<int>(document_->log()->log.knots.size())) return;
  std::vector<Knot> knots = document_->log()->log.knots;
  knots.erase(knots.begin() + knot);
  document_->editKnots(std::move(knots), tr("Delete knot %1").arg(knot + 1));
}

void LogBoardController::editKnot(int knot, const KnotShape& shape) {
  if (!document_->log() || knot < 0 || knot >= static_cast<int>(document_->log()->log.knots.size())) return;
  std::vector<Knot> knots = document_->log()->log.knots;
  knots[knot] = makeKnot(shape, knots[knot].distanceStep, knots[knot].endDistance);
  try {
    document_->editKnots(std::move(knots), tr("Edit knot %1").arg(knot + 1));
  } catch (const InputError& e) {
    log("error", QString::fromUtf8(e.what()));
    views_.knotTable->setKnots(document_->log()->log.knots);  // back to what is valid
  }
}

}  // namespace kerf
