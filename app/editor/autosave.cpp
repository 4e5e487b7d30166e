#include "autosave.hpp"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>
#include <QUuid>
#include <algorithm>

#include "document.hpp"

namespace kerf {

Autosave::Autosave(Document* document, QString folder, int intervalMs, QObject* parent)
    : QObject(parent), document_(document), folder_(folder.isEmpty() ? defaultFolder() : folder) {
  sessionId_ = QString::number(QCoreApplication::applicationPid()) + "-" +
               QUuid::createUuid().toString(QUuid::WithoutBraces).left(8);
  QDir().mkpath(folder_);
  timer_.setInterval(intervalMs);
  connect(&timer_, &QTimer::timeout, this, &Autosave::saveNow);
  timer_.start();
}

QString Autosave::defaultFolder() {
  const QString overridden = qEnvironmentVariable("KERF_AUTOSAVE_DIR");
  if (!overridden.isEmpty()) return overridden;
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/autosave";
}

QString Autosave::currentFile() const {
  return folder_ + "/session-" + sessionId_ + ".kerf";
}

QStringList Autosave::leftovers() const {
  QFileInfoList files = QDir(folder_).entryInfoList({"session-*.kerf"}, QDir::Files, QDir::Time);
  QStringList out;
  for (const QFileInfo& info : files)
    if (info.absoluteFilePath() != QFileInfo(currentFile()).absoluteFilePath())
      out << info.absoluteFilePath();
  return out;
}

QString Autosave::originalPathOf(const QString& autosaveFile) {
  QFile file(autosaveFile);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return QJsonDocument::fromJson(file.readAll()).object().value("autosave_of").toString();
}

void Autosave::saveNow() {
  if (!document_->isModified()) {
    discardCurrent();
    return;
  }
  // The copy lives in the autosave folder; photo paths in it are written relative to that folder.
  QJsonObject json = QJsonDocument::fromJson(document_->snapshot(folder_)).object();
  json.insert("autosave_of", document_->filePath());
  json.insert("autosave_name", document_->name());
  QSaveFile file(currentFile());
  if (!file.open(QIODevice::WriteOnly) || file.write(QJsonDocument(json).toJson()) < 0 || !file.commit()) {
    emit failed(tr("Autosave failed: cannot write %1").arg(currentFile()));
    return;
  }
  emit saved(currentFile());
}

void Autosave::discardCurrent() {
  QFile::remove(currentFile());
}

}  // namespace kerf
