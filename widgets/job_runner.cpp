#include "job_runner.hpp"

#include <QElapsedTimer>
#include <QThread>
#include <algorithm>
#include <atomic>
#include <stop_token>

namespace kerf {

struct JobRunner::Shared {
  std::stop_source stop;
  std::atomic<double> progress{0.0};
};

namespace {

QElapsedTimer& clock() {
  static QElapsedTimer timer = [] {
    QElapsedTimer t;
    t.start();
    return t;
  }();
  return timer;
}

// "Rendering faces…" -> "Rendering faces", for sentences in the log.
QString bare(QString name) {
  while (name.endsWith(QChar(0x2026)) || name.endsWith('.')) name.chop(1);
  return name.trimmed();
}

}  // namespace

JobRunner::JobRunner(QObject* parent) : QObject(parent) {
  // Two jobs at least: a new one starts while a cancelled one winds down. Core's loops spread each
  // job over the cores themselves.
  pool_.setMaxThreadCount(std::max(4, QThread::idealThreadCount()));
  pool_.setObjectName(QStringLiteral("kerf-jobs"));
  progressTimer_.setInterval(kProgressIntervalMs);
  connect(&progressTimer_, &QTimer::timeout, this, &JobRunner::pollProgress);
  clock();
}

JobRunner::~JobRunner() {
  progressTimer_.stop();
  for (auto& [id, job] : jobs_) job.shared->stop.request_stop();
  jobs_.clear();
  pool_.waitForDone();  // anything the workers posted since is discarded with this object
}

int JobRunner::start(QString name, Work work, Callback onDone, Callback onPreview, bool cancelsPrevious) {
  if (cancelsPrevious) cancelAll();
  const int id = nextId_++;
  const bool wasBusy = isBusy();
  auto shared = std::make_shared<Shared>();
  jobs_.emplace(id, Job{name, shared, std::move(onDone), std::move(onPreview), -1.0, clock().elapsed()});
  emit jobStarted(id, name);
  emit message(QStringLiteral("info"), tr("%1: started").arg(bare(name)));
  if (!wasBusy) emit busyChanged(true);
  progressTimer_.start();

  pool_.start([this, id, shared, work = std::move(work)] {
    const Progress progress{
        [shared](double f) { shared->progress.store(std::clamp(f, 0.0, 1.0), std::memory_order_relaxed); },
        shared->stop.get_token()};
    const Preview preview = [this, id, shared](QVariant value) {
      if (shared->stop.stop_requested()) return;  // would be dropped anyway
      QMetaObject::invokeMethod(
          this, [this, id, value = std::move(value)] { deliverPreview(id, value); }, Qt::QueuedConnection);
    };
    auto post = [this](auto function) {
      QMetaObject::invokeMethod(this, std::move(function), Qt::QueuedConnection);
    };
    try {
      QVariant result = work(progress, preview);
      post([this, id, result = std::move(result)] { deliverResult(id, result); });
    } catch (const Cancelled&) {
      post([this, id] { deliverError(id, {}, true); });
    } catch (const std::exception& e) {
      post([this, id, error = QString::fromUtf8(e.what())] { deliverError(id, error, false); });
    } catch (...) {
      post([this, id] { deliverError(id, tr("unknown error"), false); });
    }
  });
  return id;
}

void JobRunner::setJobName(int id, const QString& name) {
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return;
  it->second.name = name;
  emit jobRenamed(id, name);
}

void JobRunner::cancel(int id) {
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return;
  it->second.shared->stop.request_stop();
  const QString name = it->second.name;
  removeJob(id);
  emit jobCancelled(id);
  emit message(QStringLiteral("info"), tr("%1: cancelled").arg(bare(name)));
  if (!isBusy()) emit busyChanged(false);
}

void JobRunner::cancelAll() {
  std::vector<int> ids;
  for (const auto& entry : jobs_) ids.push_back(entry.first);
  for (int id : ids) cancel(id);
}

QList<int> JobRunner::runningJobs() const {
  QList<int> ids;
  for (const auto& entry : jobs_) ids.append(entry.first);
  return ids;
}

QString JobRunner::jobName(int id) const {
  const auto it = jobs_.find(id);
  return it == jobs_.end() ? QString() : it->second.name;
}

double JobRunner::progressOf(int id) const {
  const auto it = jobs_.find(id);
  return it == jobs_.end() ? 0.0 : it->second.shared->progress.load(std::memory_order_relaxed);
}

bool JobRunner::waitForDone(int msecs) {
  return pool_.waitForDone(msecs);
}

void JobRunner::removeJob(int id) {
  jobs_.erase(id);
  if (jobs_.empty()) progressTimer_.stop();
}

void JobRunner::deliverPreview(int id, const QVariant& value) {
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || !it->second.onPreview) return;  // superseded or cancelled: stale
  const Callback onPreview = it->second.onPreview;         // the callback may start or cancel jobs
  try {
    onPreview(value);
  } catch (const std::exception& e) {
    emit message(QStringLiteral("warning"), tr("%1: preview failed: %2").arg(bare(jobName(id)), e.what()));
  }
}

void JobRunner::deliverResult(int id, const QVariant& value) {
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return;  // superseded or cancelled: the result is stale
  Job job = std::move(it->second);
  removeJob(id);  // before onDone, which may start the next job
  const double seconds = (clock().elapsed() - job.startedMs) / 1000.0;
  bool ok = true;
  QString error;
  try {
    if (job.onDone) job.onDone(value);
  } catch (const std::exception& e) {
    ok = false;
    error = QString::fromUtf8(e.what());
  }
  if (ok) {
    emit jobFinished(id);
    emit message(QStringLiteral("info"), tr("%1: done in %2 s").arg(bare(job.name)).arg(seconds, 0, 'f', 1));
  } else {
    emit jobFailed(id, error);
    emit message(QStringLiteral("error"), tr("%1 failed: %2").arg(bare(job.name), error));
  }
  if (!isBusy()) emit busyChanged(false);
}

void JobRunner::deliverError(int id, const QString& error, bool cancelled) {
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return;  // already cancelled (and reported) or superseded
  const QString name = it->second.name;
  removeJob(id);
  if (cancelled) {  // the work stopped by itself
    emit jobCancelled(id);
    emit message(QStringLiteral("info"), tr("%1: cancelled").arg(bare(name)));
  } else {
    emit jobFailed(id, error);
    emit message(QStringLiteral("error"), tr("%1 failed: %2").arg(bare(name), error));
  }
  if (!isBusy()) emit busyChanged(false);
}

void JobRunner::pollProgress() {
  std::vector<std::pair<int, double>> changed;
  for (auto& [id, job] : jobs_) {
    const double p = job.shared->progress.load(std::memory_order_relaxed);
    if (p != job.lastProgress) {
      job.lastProgress = p;
      changed.emplace_back(id, p);
    }
  }
  for (const auto& [id, p] : changed) emit jobProgress(id, p);  // slots may start or cancel jobs
}

}  // namespace kerf
