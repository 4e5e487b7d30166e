#pragma once
// The base of the editor's controllers (faces, rings, texture, log and board, export, files): each owns the
// jobs and the state of one area of the work, reaches the document, the job runner and the window (the
// parent of its dialogs) through an EditorContext, and speaks to the user by signals the window shows (the
// log, message boxes, the status bar). The window keeps the layout, the docks and the menus.
#include <QObject>
#include <QString>

class QWidget;

namespace kerf {

class Document;
class JobRunner;

struct EditorContext {
  QWidget* window;  // the parent of dialogs and message boxes
  Document* document;
  JobRunner* jobs;
};

class EditorController : public QObject {
  Q_OBJECT

 public:
  explicit EditorController(const EditorContext& context);

 signals:
  // A line for the log ("info", "warning", "error").
  void logged(const QString& level, const QString& text);
  // A (non-blocking) message box saying `text`; `error` is the window's last error from now on.
  void alerted(const QString& text, const QString& error);
  void statusShown(const QString& text, int milliseconds);

 protected:
  // In the log and a message box.
  void showError(const QString& message);
  void log(const QString& level, const QString& text) { emit logged(level, text); }

  QWidget* window_;
  Document* document_;
  JobRunner* jobs_;
};

}  // namespace kerf
