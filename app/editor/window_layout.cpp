#include "window_layout.hpp"

#include <QAction>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMainWindow>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>
#include <algorithm>

namespace kerf {
namespace {

const char* kVersionKey = "window/layoutVersion";
const char* kGeometryKey = "window/geometry";
const char* kStateKey = "window/state";
const char* kSplitterKey = "window/centralSplitter";

}  // namespace

QStringList WindowLayout::smallDockNames() {
  return {QStringLiteral("logDock"), QStringLiteral("historyDock"), QStringLiteral("logViewDock"),
          QStringLiteral("panelDock")};
}

WindowLayout::WindowLayout(QMainWindow* window, QSplitter* central)
    : QObject(window), window_(window), central_(central) {
  resetAction_ = new QAction(tr("Reset &Layout"), this);
  resetAction_->setToolTip(
      tr("Back to the default arrangement: the faces, the 3D block and the cut large, the parameters beside "
         "them, the log and the history hidden"));
  connect(resetAction_, &QAction::triggered, this, &WindowLayout::reset);
}

QDockWidget* WindowLayout::dock(const QString& objectName) const {
  return window_->findChild<QDockWidget*>(objectName);
}

void WindowLayout::arrangeDocks() {
  // The right-hand column runs the window's full height; the cut lies under the faces and the block only.
  window_->setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
  window_->setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
  for (QDockWidget* d : window_->findChildren<QDockWidget*>())
    if (d->isFloating()) d->setFloating(false);
  QDockWidget* parameters = dock("parametersDock");
  QDockWidget* cut = dock("cutDock");
  if (parameters) window_->addDockWidget(Qt::RightDockWidgetArea, parameters);  // moves it back if elsewhere
  if (cut) window_->addDockWidget(Qt::BottomDockWidgetArea, cut);
  // The small group: tabbed below the parameters (split before the parameters are tabbed with the board:
  // a dock in a tab group can only gain tabs).
  QDockWidget* first = nullptr;
  for (const QString& name : smallDockNames()) {
    QDockWidget* d = dock(name);
    if (!d) continue;
    d->hide();
    if (!first) {
      window_->addDockWidget(Qt::RightDockWidgetArea, d);
      if (parameters) window_->splitDockWidget(parameters, d, Qt::Vertical);
      first = d;
    } else {
      window_->tabifyDockWidget(first, d);
    }
  }
  // The block's knots and the board: tabs beside the parameters, shown while there is something in them.
  for (const char* name : {"blockKnotsDock", "boardDock"}) {
    QDockWidget* tab = dock(name);
    if (!tab || !parameters) continue;
    const bool shown = tab->isVisible();
    window_->addDockWidget(Qt::RightDockWidgetArea, tab);
    window_->tabifyDockWidget(parameters, tab);
    tab->setVisible(shown);
  }
  for (QDockWidget* d : {parameters, cut})
    if (d) {
      d->show();
      d->raise();
    }
}

// Once the window has its size: the cut gets about 40 % of the height under the faces and the block, the
// parameters a quarter of the width (narrower on small screens), the faces a little more than the block
// (their cross is 4 faces wide and 3 high).
void WindowLayout::sizeDocks() {
  QDockWidget* parameters = dock("parametersDock");
  QDockWidget* cut = dock("cutDock");
  const int width = window_->width(), height = window_->height();
  if (parameters) window_->resizeDocks({parameters}, {std::clamp(width / 4, 300, 440)}, Qt::Horizontal);
  if (cut) window_->resizeDocks({cut}, {std::max(220, height * 2 / 5)}, Qt::Vertical);
  const int rest = std::max(2, central_->width());
  central_->setSizes({rest * 11 / 20, rest - rest * 11 / 20});
}

void WindowLayout::reset() {
  arrangeDocks();
  QTimer::singleShot(0, this, [this] { sizeDocks(); });
}

void WindowLayout::restore() {
  arrangeDocks();
  QSettings settings;
  const QByteArray state = settings.value(kStateKey).toByteArray();
  const bool useSaved = !state.isEmpty() && settings.value(kVersionKey).toInt() == kVersion &&
                        !qEnvironmentVariableIsSet("KERF_DEFAULT_LAYOUT");
  if (useSaved && window_->restoreState(state, kVersion)) {
    window_->restoreGeometry(settings.value(kGeometryKey).toByteArray());
    central_->restoreState(settings.value(kSplitterKey).toByteArray());
    return;
  }
  // The default: most of the screen, at most 1600 x 1000.
  if (const QScreen* screen = QGuiApplication::primaryScreen()) {
    const QSize available = screen->availableGeometry().size();
    window_->resize(std::min(1600, available.width() * 92 / 100),
                    std::min(1000, available.height() * 92 / 100));
  }
  QTimer::singleShot(0, this, [this] { sizeDocks(); });
}

void WindowLayout::save() const {
  QSettings settings;
  settings.setValue(kVersionKey, kVersion);
  settings.setValue(kGeometryKey, window_->saveGeometry());
  settings.setValue(kStateKey, window_->saveState(kVersion));
  settings.setValue(kSplitterKey, central_->saveState());
}

void WindowLayout::addDockButtons(QStatusBar* bar) {
  for (const char* name : {"logDock", "historyDock"}) {
    QDockWidget* d = dock(name);
    if (!d) continue;
    auto* button = new QToolButton(bar);
    button->setObjectName(QStringLiteral("%1Button").arg(name));
    button->setDefaultAction(d->toggleViewAction());  // follows the dock's title: "Log (2 errors)"
    button->setAutoRaise(true);
    bar->addPermanentWidget(button);
  }
}

void WindowLayout::showDock(const QString& objectName) {
  if (QDockWidget* d = dock(objectName)) {
    d->show();
    d->raise();
  }
}

}  // namespace kerf
