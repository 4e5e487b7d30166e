#pragma once
// Autosave and recovery: while a document has unsaved changes, a copy is written every few seconds
// to the autosave folder (atomically). A clean close removes it; a copy found at start-up means Kerf
// did not close cleanly, and the editor offers to recover it. The timer's copies are serialised and
// written on a worker thread (a project with a CT log is megabytes of JSON: the GUI must not stall on
// it every few seconds), and only when the text differs from the last copy written.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <cstddef>

namespace kerf {

class Document;

class Autosave : public QObject {
  Q_OBJECT

 public:
  // `folder`: where copies go (default: QStandardPaths::AppDataLocation + "/autosave"; the
  // KERF_AUTOSAVE_DIR environment variable overrides it, for tests).
  Autosave(Document* document, QString folder = {}, int intervalMs = 5000, QObject* parent = nullptr);

  static QString defaultFolder();
  QString folder() const { return folder_; }
  // The copy of the current document (exists only while there are unsaved changes).
  QString currentFile() const;

  // Copies left behind by earlier sessions (not this one's), newest first.
  QStringList leftovers() const;
  // The file the copy was made from ("" for a document that had none), read from the copy.
  static QString originalPathOf(const QString& autosaveFile);

  ~Autosave() override;
  // Writes the copy now, on this thread, if the document has unsaved changes, else removes it.
  void saveNow();
  void discardCurrent();  // removes this session's copy (after a save or a deliberate discard)

 signals:
  void saved(QString file);
  void failed(QString message);

 private:
  struct Written {
    QString error;         // empty on success
    std::size_t hash = 0;  // of the text written (or found unchanged)
    bool wrote = false;
  };
  void saveInBackground();  // the timer's path
  void backgroundDone();
  Written write(const QByteArray& text) const;

  Document* document_;
  QString folder_;
  QString sessionId_;
  QTimer timer_;
  QFutureWatcher<Written> writer_;
  std::size_t lastHash_ = 0;  // of the copy on disk (0: none)
  int generation_ = 0;        // bumped by discardCurrent(): a write started before it is void
  int writerGeneration_ = 0;
};

}  // namespace kerf
