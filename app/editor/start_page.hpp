#pragma once
// What the editor shows where the faces go while no document is open (issue 20, "a path through the
// work"): open a folder of face photos, open a project, open the demo block, or one of the recent files,
// and what comes next (Reconstruct). It only asks; the main window opens.
#include <QWidget>

class QListWidget;
class QPushButton;

namespace kerf {

class RecentFiles;

class StartPage : public QWidget {
  Q_OBJECT

 public:
  StartPage(RecentFiles* recent, QWidget* parent = nullptr);

  QPushButton* photosButton() const { return photos_; }
  QPushButton* projectButton() const { return project_; }
  QPushButton* demoButton() const { return demo_; }
  QListWidget* recentList() const { return recentList_; }

 signals:
  void openPhotosRequested();
  void openProjectRequested();
  void demoRequested();
  void recentRequested(const QString& path);

 private:
  void refresh();

  RecentFiles* recent_;
  QPushButton* photos_;
  QPushButton* project_;
  QPushButton* demo_;
  QListWidget* recentList_;
};

}  // namespace kerf
