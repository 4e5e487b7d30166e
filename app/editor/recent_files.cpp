#include "recent_files.hpp"

#include <QFileInfo>
#include <QSettings>

namespace kerf {
namespace {
constexpr int kMaxRecent = 10;
const char* kKey = "recentFiles";
}  // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu) {
  connect(menu_, &QMenu::aboutToShow, this, &RecentFiles::rebuildMenu);
  rebuildMenu();
}

QStringList RecentFiles::files() const {
  return QSettings().value(kKey).toStringList();
}

void RecentFiles::add(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList list = files();
  list.removeAll(absolute);
  list.prepend(absolute);
  while (list.size() > kMaxRecent) list.removeLast();
  QSettings().setValue(kKey, list);
  rebuildMenu();
}

void RecentFiles::clear() {
  QSettings().remove(kKey);
  rebuildMenu();
}

void RecentFiles::rebuildMenu() {
  QStringList list = files();
  list.erase(std::remove_if(list.begin(), list.end(), [](const QString& f) { return !QFileInfo::exists(f); }),
             list.end());
  QSettings().setValue(kKey, list);
  menu_->clear();
  for (int i = 0; i < list.size(); ++i) {
    const QString path = list[i];
    QAction* action = menu_->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
    action->setToolTip(path);
    action->setStatusTip(path);
    connect(action, &QAction::triggered, this, [this, path] { emit openRequested(path); });
  }
  if (list.isEmpty()) menu_->addAction(tr("No recent files"))->setEnabled(false);
  emit listChanged();
  menu_->addSeparator();
  menu_->addAction(tr("Clear list"), this, &RecentFiles::clear)->setEnabled(!list.isEmpty());
}

}  // namespace kerf
