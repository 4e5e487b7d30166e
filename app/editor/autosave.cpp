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
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/project.hpp"

#include "background_pool.hpp"
#include "document.hpp"

namespace kerf {

Autosave::Autosave(Document* document, QString folder, int intervalMs, QObject* parent)
    : QObject(parent), document_(document), folder_(folder.isEmpty() ? defaultFolder() : folder) {
  sessionId_ = QString::number(QCoreApplication::applicationPid()) + "-" +
               QUuid::createUuid().toString(QUuid::WithoutBraces).left(8);
  QDir().mkpath(folder_);
  timer_.setInterval(intervalMs);
  connect(&timer_, &QTimer::timeout, this, &Autosave::saveInBackground);
  connect(&writer_, &QFutureWatcher<Written>::finished, this, &Autosave::backgroundDone);
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

Autosave::~Autosave() {
  writer_.waitForFinished();
}

namespace {

// The copy's text: the project (photo paths relative to the autosave folder) and where it came from.
QByteArray autosaveText(const Project& project, const QString& folder, const QString& original,
                        const QString& name) {
  nlohmann::json json = projectToJson(project, std::filesystem::absolute(folder.toStdString()));
  json["autosave_of"] = original.toStdString();
  json["autosave_name"] = name.toStdString();
  return QByteArray::fromStdString(json.dump(2));
}

std::size_t hashOf(const QByteArray& text) {
  return std::hash<std::string_view>{}(std::string_view(text.constData(), text.size())) | 1;  // never 0
}

}  // namespace

Autosave::Written Autosave::write(const QByteArray& text) const {
  Written result;
  result.hash = hashOf(text);
  QSaveFile file(currentFile());
  if (!file.open(QIODevice::WriteOnly) || file.write(text) < 0 || !file.commit()) {
    result.error = tr("Autosave failed: cannot write %1").arg(currentFile());
  }
  result.wrote = result.error.isEmpty();
  return result;
}

void Autosave::saveNow() {
  writer_.waitForFinished();
  if (!document_->isModified()) {
    discardCurrent();
    return;
  }
  const Written written =
      write(autosaveText(document_->project(), folder_, document_->filePath(), document_->name()));
  if (!written.error.isEmpty()) {
    emit failed(written.error);
    return;
  }
  lastHash_ = written.hash;
  emit saved(currentFile());
}

void Autosave::saveInBackground() {
  if (writer_.isRunning()) return;  // the next tick takes the newer state
  if (!document_->isModified()) {
    discardCurrent();
    return;
  }
  // Copied here, on the GUI thread (cheap next to serialising it); the worker owns the copy.
  const Project project = document_->project();
  const QString original = document_->filePath(), name = document_->name(), folder = folder_;
  const std::size_t last = lastHash_;
  writerGeneration_ = generation_;
  writer_.setFuture(QtConcurrent::run(backgroundPool(), [this, project, original, name, folder, last] {
    const QByteArray text = autosaveText(project, folder, original, name);
    if (hashOf(text) == last) return Written{{}, last, false};  // unchanged since the last copy
    return write(text);
  }));
}

void Autosave::backgroundDone() {
  const Written written = writer_.result();
  if (writerGeneration_ != generation_) {  // discarded while it was being written
    if (written.wrote) QFile::remove(currentFile());
    return;
  }
  if (!written.error.isEmpty()) {
    emit failed(written.error);
    return;
  }
  lastHash_ = written.hash;
  if (written.wrote) emit saved(currentFile());
}

void Autosave::discardCurrent() {
  ++generation_;
  lastHash_ = 0;
  QFile::remove(currentFile());
}

}  // namespace kerf
