#pragma once
// File > Open Recent: the last documents opened or saved, kept in QSettings, newest first, at most
// ten, files that no longer exist pruned when the menu is shown.
#include <QMenu>
#include <QObject>
#include <QStringList>

namespace kerf {

class RecentFiles : public QObject {
  Q_OBJECT

 public:
  explicit RecentFiles(QMenu* menu, QObject* parent = nullptr);

  void add(const QString& path);
  QStringList files() const;
  void clear();

 signals:
  void openRequested(QString path);
  void listChanged();  // added, cleared or pruned (the start page lists them too)

 private:
  void rebuildMenu();
  QMenu* menu_;
};

}  // namespace kerf
