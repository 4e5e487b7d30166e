#include "job_status_widget.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QShortcut>
#include <QToolButton>
#include <cmath>

#include "job_runner.hpp"

namespace kerf {

JobStatusWidget::JobStatusWidget(JobRunner* runner, QWidget* parent) : QWidget(parent), runner_(runner) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(6);
  label_ = new QLabel(this);
  bar_ = new QProgressBar(this);
  bar_->setRange(0, 100);
  bar_->setMaximumWidth(180);
  bar_->setMaximumHeight(16);
  bar_->setTextVisible(false);
  cancel_ = new QToolButton(this);
  cancel_->setText(tr("Cancel"));
  cancel_->setToolTip(tr("Cancel the running job (Esc)"));
  cancel_->setAutoRaise(true);
  layout->addWidget(label_);
  layout->addWidget(bar_);
  layout->addWidget(cancel_);
  connect(cancel_, &QToolButton::clicked, this, &JobStatusWidget::cancelShownJob);

  // Esc anywhere in the window cancels, but only while something runs (Esc keeps its other uses).
  escape_ = new QShortcut(QKeySequence(Qt::Key_Escape), this);
  escape_->setContext(Qt::WindowShortcut);
  escape_->setEnabled(false);
  connect(escape_, &QShortcut::activated, this, &JobStatusWidget::cancelShownJob);

  connect(runner_, &JobRunner::jobStarted, this, &JobStatusWidget::refresh);
  connect(runner_, &JobRunner::jobRenamed, this, &JobStatusWidget::refresh);
  connect(runner_, &JobRunner::jobFinished, this, &JobStatusWidget::refresh);
  connect(runner_, &JobRunner::jobFailed, this, &JobStatusWidget::refresh);
  connect(runner_, &JobRunner::jobCancelled, this, &JobStatusWidget::refresh);
  connect(runner_, &JobRunner::jobProgress, this, &JobStatusWidget::setProgress);
  refresh();
}

QString JobStatusWidget::text() const {
  return label_->text();
}

int JobStatusWidget::progressPercent() const {
  return bar_->value();
}

void JobStatusWidget::cancelShownJob() {
  if (shownJob_) runner_->cancel(shownJob_);
}

void JobStatusWidget::refresh() {
  const QList<int> jobs = runner_->runningJobs();
  const int newest = jobs.isEmpty() ? 0 : jobs.back();
  escape_->setEnabled(newest != 0);
  setVisible(newest != 0);
  if (newest == 0) {
    shownJob_ = 0;
    return;
  }
  QString text = runner_->jobName(newest);
  if (jobs.size() > 1) text += tr(" (+%1)").arg(jobs.size() - 1);
  label_->setText(text);
  if (newest != shownJob_) {
    shownJob_ = newest;
    setProgress(newest, runner_->progressOf(newest));
  }
}

void JobStatusWidget::setProgress(int id, double fraction) {
  if (id == shownJob_) bar_->setValue(static_cast<int>(std::lround(fraction * 100)));
}

}  // namespace kerf
