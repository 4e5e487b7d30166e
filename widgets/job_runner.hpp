#pragma once
// Runs the editor's long work (rendering, loading, exports, fitting) off the GUI thread, on the
// runner's own thread pool, and brings results back to the GUI thread.
//
// A job is a function `work(progress, preview)`: it reports its fraction done through
// progress.set(), checks progress.stop (core throws kerf::Cancelled when it is requested), may hand
// intermediate results to preview(), and returns its result. Everything it gives back (previews,
// the result, an error) arrives on the GUI thread through queued calls, in the order it was sent.
// A job that is cancelled, or superseded by a newer one, is dropped: neither onPreview nor onDone is
// called for it any more, even if its work still returns a result.
//
// Signals: jobStarted, jobProgress (polled, ~20 Hz, only on change), then exactly one of jobFinished
// (after onDone), jobFailed (kerf::InputError / std::exception message; onDone is not called) or
// jobCancelled (emitted at once by cancel(), while the work winds down in the background).
// message() says the same for the log: level "info", "warning" or "error".
//
// Use it from the GUI thread (the thread it lives in). The destructor cancels every job and waits for
// the work to return; nothing is delivered after it.
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QTimer>
#include <QVariant>
#include <functional>
#include <map>
#include <memory>

#include "util/progress.hpp"

namespace kerf {

class JobRunner : public QObject {
  Q_OBJECT

 public:
  using Preview = std::function<void(QVariant)>;
  using Work = std::function<QVariant(const Progress& progress, const Preview& preview)>;
  using Callback = std::function<void(QVariant)>;

  explicit JobRunner(QObject* parent = nullptr);
  ~JobRunner() override;

  // Starts `work` and returns the job's id (> 0). With cancelsPrevious, every job still running is
  // cancelled first (the usual case: a new render replaces the old one); without, it runs beside them.
  // onDone and onPreview run on the GUI thread.
  int start(QString name, Work work, Callback onDone, Callback onPreview = {}, bool cancelsPrevious = true);

  void cancel(int id);  // no-op for a job that is not running
  // A job of named stages says which one it is in (jobRenamed); no-op for a job that is not running.
  void setJobName(int id, const QString& name);
  void cancelAll();

  bool isBusy() const { return !jobs_.empty(); }  // some job has neither finished nor been cancelled
  bool isRunning(int id) const { return jobs_.count(id) > 0; }
  QList<int> runningJobs() const;  // oldest first
  QString jobName(int id) const;
  double progressOf(int id) const;  // last fraction reported, 0..1

  // Blocks until every job's work has returned, including cancelled ones that are winding down
  // (tests, shutdown). Does not deliver their results; run the event loop for that.
  bool waitForDone(int msecs = -1);

  static constexpr int kProgressIntervalMs = 50;  // jobProgress at most ~20 times a second per job

 signals:
  void jobStarted(int id, const QString& name);
  void jobRenamed(int id, const QString& name);
  void jobProgress(int id, double fraction);
  void jobFinished(int id);
  void jobFailed(int id, const QString& message);
  void jobCancelled(int id);
  void message(const QString& level, const QString& text);
  void busyChanged(bool busy);

 private:
  struct Shared;  // what the worker thread and the GUI thread both see
  struct Job {
    QString name;
    std::shared_ptr<Shared> shared;
    Callback onDone, onPreview;
    double lastProgress = -1;
    qint64 startedMs = 0;
  };
  void deliverPreview(int id, const QVariant& value);
  void deliverResult(int id, const QVariant& value);
  void deliverError(int id, const QString& error, bool cancelled);
  void pollProgress();
  void removeJob(int id);

  QThreadPool pool_;
  QTimer progressTimer_;
  std::map<int, Job> jobs_;  // running jobs, by id (ids grow, so oldest first)
  int nextId_ = 1;
};

}  // namespace kerf
