// MainWindow: the docks of knots, logs and boards: the "Knots" dock, the block's knot table
// (docs/editor.md, "Knots in the block"; BlockKnotsController drives it), and (docs/editor.md, "Logs and
// boards") the "Log view" dock (widgets/log_view.hpp), the "Board" dock (placement, the log's knot table and
// the panel choice) and the "Panel" view (LogBoardController drives them).
#include <QDockWidget>
#include <QSplitter>
#include <QTabWidget>
#include <QVBoxLayout>

#include "block_knot_table.hpp"
#include "board_controls.hpp"
#include "image_pane.hpp"
#include "knot_table.hpp"
#include "log_view.hpp"
#include "main_window.hpp"
#include "panel_controls.hpp"

namespace kerf {

void MainWindow::createBlockKnotsDock() {
  blockKnotTable_ = new BlockKnotTable(this);
  auto* dock = new QDockWidget(tr("Knots"), this);
  dock->setObjectName("blockKnotsDock");
  dock->setToolTip(tr("The block's knots: where each branch runs, how thick it is and when it died"));
  dock->setWidget(blockKnotTable_);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  if (auto* parameters = findChild<QDockWidget*>("parametersDock")) {
    tabifyDockWidget(parameters, dock);
    parameters->raise();
  }
  dock->hide();  // shown with a block that has knots (BlockKnotsController)
}

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
}

void MainWindow::createPanelDock(QTabWidget* boardTabs) {
  auto* page = new QWidget(boardTabs);
  auto* layout = new QVBoxLayout(page);
  panelControls_ = new PanelControls(page);
  layout->addWidget(panelControls_);
  layout->addStretch(1);
  boardTabs->addTab(page, tr("Panel"));

  panelPane_ = new ImagePane(this);
  panelPane_->setPlaceholder(tr("Choose a panel in the Board dock and press Show Panel"));
  auto* dock = new QDockWidget(tr("Panel"), this);
  dock->setObjectName("panelDock");
  dock->setWidget(panelPane_);
  addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (auto* logViewDock = findChild<QDockWidget*>("logViewDock")) tabifyDockWidget(logViewDock, dock);
  dock->hide();  // shown with the first panel
}

}  // namespace kerf
