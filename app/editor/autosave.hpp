#pragma once
// Autosave and recovery: while a document has unsaved changes, a copy is written every few seconds
// to the autosave folder (atomically). A clean close removes it; a copy found at start-up means Kerf
// did not close cleanly, and the editor offers to recover it.
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

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

  void saveNow();         // writes the copy if the document has unsaved changes, else removes it
  void discardCurrent();  // removes this session's copy (after a save or a deliberate discard)

 signals:
  void saved(QString file);
  void failed(QString message);

 private:
  Document* document_;
  QString folder_;
  QString sessionId_;
  QTimer timer_;
};

}  // namespace kerf
