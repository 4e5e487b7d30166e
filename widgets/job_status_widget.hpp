#pragma once
// The running job in the status bar: its name, a progress bar and a Cancel button (Esc while busy).
// Shows the newest running job of a JobRunner ("+N" when more run beside it); hidden when idle.
#include <QWidget>

class QLabel;
class QProgressBar;
class QShortcut;
class QToolButton;

namespace kerf {

class JobRunner;

class JobStatusWidget : public QWidget {
  Q_OBJECT

 public:
  explicit JobStatusWidget(JobRunner* runner, QWidget* parent = nullptr);

  int shownJob() const { return shownJob_; }  // 0 when idle
  QString text() const;                       // the label, for tests
  int progressPercent() const;                // the bar, for tests
  QToolButton* cancelButton() const { return cancel_; }

 public slots:
  void cancelShownJob();

 private:
  void refresh();
  void setProgress(int id, double fraction);

  JobRunner* runner_;
  int shownJob_ = 0;
  QLabel* label_;
  QProgressBar* bar_;
  QToolButton* cancel_;
  QShortcut* escape_;
};

}  // namespace kerf
