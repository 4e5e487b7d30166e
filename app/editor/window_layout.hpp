#pragma once
// The main window's arrangement (issue 20, "a layout for the job"): the faces and the 3D block side by side
// above the true-scale cut, which together take most of the window; the parameters beside them on the
// right; the log, the history, the log view and the panel small, tabbed under the parameters and hidden
// until wanted (View menu, or the status bar's buttons). The arrangement a user makes is remembered per
// user (QSettings, with a version number: a layout saved by an older arrangement is not restored) and
// View > Reset Layout brings back the default.
#include <QByteArray>
#include <QObject>
#include <QStringList>

class QAction;
class QDockWidget;
class QMainWindow;
class QSplitter;
class QStatusBar;

namespace kerf {

class WindowLayout : public QObject {
  Q_OBJECT

 public:
  // Bump when the docks or the central splitter change, so that old saved states are ignored.
  static constexpr int kVersion = 4;
  // The docks of the small, hidden-until-wanted group, by object name.
  static QStringList smallDockNames();

  // `central`: the faces | 3D block splitter. The docks are found by their object names.
  WindowLayout(QMainWindow* window, QSplitter* central);

  // The saved layout when there is one of this version (and KERF_DEFAULT_LAYOUT is unset), else the
  // default (applied once the window has its size).
  void restore();
  void save() const;
  // The default arrangement, at the window's current size.
  void reset();
  QAction* resetAction() const { return resetAction_; }

  // Buttons in the status bar that show / hide the log and the history (their docks' toggle actions).
  void addDockButtons(QStatusBar* bar);
  // Shows and raises a dock of the small group (a status-bar button, an error in the log).
  void showDock(const QString& objectName);

 private:
  void arrangeDocks();
  void sizeDocks();
  QDockWidget* dock(const QString& objectName) const;

  QMainWindow* window_;
  QSplitter* central_;
  QAction* resetAction_;
};

}  // namespace kerf
