// JobRunner, JobStatusWidget and LogPanel: results on the GUI thread, throttled progress, cancelling,
// superseding, failures, previews in order, shutdown; the status widget and the log.
#include <QApplication>
#include <QClipboard>
#include <QElapsedTimer>
#include <QProgressBar>
#include <QSignalSpy>
#include <QThread>
#include <QToolButton>
#include <QtTest>
#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "../timing_checks.hpp"
#include "job_runner.hpp"
#include "job_status_widget.hpp"
#include "log_panel.hpp"
#include "util/error.hpp"

using namespace kerf;
using namespace std::chrono_literals;

namespace {

constexpr int kTimeoutMs = 10000;

// Work that runs until cancelled (or `limit`), reporting progress and checking the stop token the way
// core's loops do.
// `ranOut` says that the limit, not a cancel, ended it.
JobRunner::Work untilCancelled(std::atomic<bool>* returned = nullptr, std::chrono::milliseconds limit = 20s,
                               std::atomic<bool>* ranOut = nullptr) {
  return [returned, limit, ranOut](const Progress& progress, const JobRunner::Preview&) -> QVariant {
    const auto start = std::chrono::steady_clock::now();
    struct Flag {
      std::atomic<bool>* flag;
      ~Flag() {
        if (flag) flag->store(true);
      }
    } flag{returned};
    while (std::chrono::steady_clock::now() - start < limit) {
      progress.throwIfCancelled();
      progress.set(std::chrono::duration<double>(std::chrono::steady_clock::now() - start) / limit);
      std::this_thread::sleep_for(2ms);
    }
    if (ranOut) ranOut->store(true);
    return QStringLiteral("ran out");
  };
}

}  // namespace

class TestJobs : public QObject {
  Q_OBJECT

 private slots:
  void resultArrivesOnGuiThread();
  void startNeverBlocks();
  void progressIsThrottled();
  void cancelStopsALongJob();
  void newerJobSupersedesOlder();
  void jobsBesideEachOther();
  void failuresCarryTheMessage();
  void previewsArriveInOrder();
  void destructorCancelsAndWaits();
  void statusWidgetFollowsJobs();
  void logPanel();
};

void TestJobs::resultArrivesOnGuiThread() {
  JobRunner runner;
  QThread* workThread = nullptr;
  QThread* doneThread = nullptr;
  QVariant result;
  QSignalSpy started(&runner, &JobRunner::jobStarted);
  QSignalSpy finished(&runner, &JobRunner::jobFinished);
  QSignalSpy messages(&runner, &JobRunner::message);
  const int id = runner.start(
      "Adding",
      [&](const Progress&, const JobRunner::Preview&) {
        workThread = QThread::currentThread();
        return QVariant(6 * 7);
      },
      [&](QVariant value) {
        doneThread = QThread::currentThread();
        result = value;
      });
  QVERIFY(id > 0);
  QCOMPARE(started.count(), 1);
  QCOMPARE(started.at(0).at(1).toString(), QStringLiteral("Adding"));
  QVERIFY(runner.isBusy());
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
  QCOMPARE(finished.at(0).at(0).toInt(), id);
  QCOMPARE(result.toInt(), 42);
  QVERIFY(workThread != nullptr && workThread != qApp->thread());
  QCOMPARE(doneThread, qApp->thread());
  QVERIFY(!runner.isBusy());
  QVERIFY(messages.count() >= 2);  // started, done
  QCOMPARE(messages.last().at(0).toString(), QStringLiteral("info"));
}

void TestJobs::startNeverBlocks() {
  // The work waits until the test releases it (or 20 s pass): had start() waited for the work, the work
  // would have run out before start() returned. No clock decides the verdict.
  JobRunner runner;
  auto released = std::make_shared<std::atomic<bool>>(false);
  QString result;
  bool done = false;
  runner.start(
      "Waiting",
      [released](const Progress&, const JobRunner::Preview&) {
        const auto until = std::chrono::steady_clock::now() + 20s;
        while (!released->load() && std::chrono::steady_clock::now() < until)
          std::this_thread::sleep_for(1ms);
        return QVariant(released->load() ? QStringLiteral("released") : QStringLiteral("ran out"));
      },
      [&](QVariant value) {
        done = true;
        result = value.toString();
      });
  QVERIFY(!done);
  released->store(true);
  QTRY_VERIFY_WITH_TIMEOUT(done, kTimeoutMs);
  QCOMPARE(result, QStringLiteral("released"));  // start() returned while the work was still waiting
}

void TestJobs::progressIsThrottled() {
  JobRunner runner;
  QSignalSpy progress(&runner, &JobRunner::jobProgress);
  QSignalSpy finished(&runner, &JobRunner::jobFinished);
  QElapsedTimer timer;
  timer.start();
  runner.start("Counting",
               [](const Progress& p, const JobRunner::Preview&) {
                 for (int i = 1; i <= 4000; ++i) {  // far more reports than the GUI should see
                   p.set(i / 4000.0);
                   if (i % 10 == 0) std::this_thread::sleep_for(1ms);
                 }
                 return QVariant();
               },
               {});
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
  const double seconds = timer.elapsed() / 1000.0;
  qInfo() << progress.count() << "progress signals in" << seconds << "s";
  QVERIFY(progress.count() >= 2);
  QVERIFY(progress.count() <= seconds * 1000 / JobRunner::kProgressIntervalMs + 3);  // ~20 Hz at most
  double last = -1;
  for (const QList<QVariant>& args : progress) {
    QVERIFY(args.at(1).toDouble() >= last);
    last = args.at(1).toDouble();
    QVERIFY(last >= 0 && last <= 1);
  }
}

void TestJobs::cancelStopsALongJob() {
  JobRunner runner;
  std::atomic<bool> returned{false};
  bool doneCalled = false;
  QSignalSpy cancelled(&runner, &JobRunner::jobCancelled);
  QSignalSpy finished(&runner, &JobRunner::jobFinished);
  QSignalSpy failed(&runner, &JobRunner::jobFailed);
  QSignalSpy progress(&runner, &JobRunner::jobProgress);
  const int id = runner.start("Forever", untilCancelled(&returned), [&](QVariant) { doneCalled = true; });
  QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 0, kTimeoutMs);
  QElapsedTimer timer;
  timer.start();
  runner.cancel(id);
  QCOMPARE(cancelled.count(), 1);  // at once
  QCOMPARE(cancelled.at(0).at(0).toInt(), id);
  QVERIFY(!runner.isBusy());
  QVERIFY(runner.waitForDone(kTimeoutMs));
  QVERIFY(returned.load());
  qInfo() << "the work stopped" << timer.elapsed() << "ms after cancel()";
  if (kerf::testing::timingChecks()) QVERIFY(timer.elapsed() < 1000);
  QTest::qWait(50);  // let anything queued arrive
  QVERIFY(!doneCalled);
  QCOMPARE(finished.count(), 0);
  QCOMPARE(failed.count(), 0);
  QCOMPARE(cancelled.count(), 1);
  runner.cancel(id);  // again: nothing
  QCOMPARE(cancelled.count(), 1);
}

void TestJobs::newerJobSupersedesOlder() {
  JobRunner runner;
  QStringList results;
  QSignalSpy cancelled(&runner, &JobRunner::jobCancelled);
  QSignalSpy finished(&runner, &JobRunner::jobFinished);
  // The old job ignores the stop request for a while and still returns a (stale) result.
  const int old = runner.start(
      "Old",
      [](const Progress&, const JobRunner::Preview&) {
        std::this_thread::sleep_for(200ms);
        return QVariant(QStringLiteral("old"));
      },
      [&](QVariant v) { results << v.toString(); });
  const int newer = runner.start(
      "New", [](const Progress&, const JobRunner::Preview&) { return QVariant(QStringLiteral("new")); },
      [&](QVariant v) { results << v.toString(); });
  QCOMPARE(cancelled.count(), 1);
  QCOMPARE(cancelled.at(0).at(0).toInt(), old);
  QVERIFY(!runner.isRunning(old));
  QVERIFY(runner.isRunning(newer) || finished.count() == 1);
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
  QVERIFY(runner.waitForDone(kTimeoutMs));
  QTest::qWait(50);
  QCOMPARE(results, QStringList{"new"});  // the old result was dropped
  QCOMPARE(finished.at(0).at(0).toInt(), newer);
}

void TestJobs::jobsBesideEachOther() {
  JobRunner runner;
  QSignalSpy finished(&runner, &JobRunner::jobFinished);
  QSignalSpy cancelled(&runner, &JobRunner::jobCancelled);
  int done = 0;
  auto sleepy = [](const Progress&, const JobRunner::Preview&) {
    std::this_thread::sleep_for(100ms);
    return QVariant();
  };
  runner.start("Export", sleepy, [&](QVariant) { ++done; });
  runner.start(
      "Render", sleepy, [&](QVariant) { ++done; }, {}, /*cancelsPrevious=*/false);
  QCOMPARE(runner.runningJobs().size(), 2);
  QTRY_COMPARE_WITH_TIMEOUT(done, 2, kTimeoutMs);
  QCOMPARE(cancelled.count(), 0);
  runner.start("A", untilCancelled(), {});
  runner.start("B", untilCancelled(), {}, {}, false);
  runner.cancelAll();
  QCOMPARE(cancelled.count(), 2);
  QVERIFY(!runner.isBusy());
}

void TestJobs::failuresCarryTheMessage() {
  JobRunner runner;
  QSignalSpy failed(&runner, &JobRunner::jobFailed);
  QSignalSpy messages(&runner, &JobRunner::message);
  bool doneCalled = false;
  const int input = runner.start(
      "Loading",
      [](const Progress&, const JobRunner::Preview&) -> QVariant {
        throw InputError("cannot read A_col.png: not a PNG file");
      },
      [&](QVariant) { doneCalled = true; });
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kTimeoutMs);
  QCOMPARE(failed.at(0).at(0).toInt(), input);
  QCOMPARE(failed.at(0).at(1).toString(), QStringLiteral("cannot read A_col.png: not a PNG file"));
  QVERIFY(!doneCalled);
  QCOMPARE(messages.last().at(0).toString(), QStringLiteral("error"));
  QVERIFY(messages.last().at(1).toString().contains("not a PNG file"));

  runner.start(
      "Exporting",
      [](const Progress&, const JobRunner::Preview&) -> QVariant { throw std::runtime_error("disk full"); },
      {});
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 2, kTimeoutMs);
  QCOMPARE(failed.at(1).at(1).toString(), QStringLiteral("disk full"));

  // A job that stops by itself with Cancelled is cancelled, not failed.
  QSignalSpy cancelled(&runner, &JobRunner::jobCancelled);
  runner.start("Stopping", [](const Progress&, const JobRunner::Preview&) -> QVariant { throw Cancelled(); },
               {});
  QTRY_COMPARE_WITH_TIMEOUT(cancelled.count(), 1, kTimeoutMs);
  QCOMPARE(failed.count(), 2);

  // onDone throwing is reported the same way.
  runner.start(
      "Showing", [](const Progress&, const JobRunner::Preview&) { return QVariant(1); },
      [](QVariant) { throw InputError("bad result"); });
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 3, kTimeoutMs);
  QCOMPARE(failed.at(2).at(1).toString(), QStringLiteral("bad result"));
}

void TestJobs::previewsArriveInOrder() {
  JobRunner runner;
  QList<int> previews;
  int previewsAtDone = -1;
  QThread* previewThread = nullptr;
  runner.start(
      "Refining",
      [](const Progress&, const JobRunner::Preview& preview) {
        for (int i = 0; i < 50; ++i) preview(QVariant(i));
        return QVariant(50);
      },
      [&](QVariant) { previewsAtDone = static_cast<int>(previews.size()); },
      [&](QVariant v) {
        previewThread = QThread::currentThread();
        previews << v.toInt();
      });
  QTRY_VERIFY_WITH_TIMEOUT(previewsAtDone >= 0, kTimeoutMs);
  QCOMPARE(previewsAtDone, 50);  // every preview before the result
  QList<int> expected;
  for (int i = 0; i < 50; ++i) expected << i;
  QCOMPARE(previews, expected);
  QCOMPARE(previewThread, qApp->thread());

  // Previews of a cancelled job are dropped.
  int stale = 0;
  const int id = runner.start(
      "Stale",
      [](const Progress& progress, const JobRunner::Preview& preview) {
        std::this_thread::sleep_for(50ms);
        for (int i = 0; i < 5; ++i) preview(QVariant(i));
        return QVariant();
      },
      {}, [&](QVariant) { ++stale; });
  runner.cancel(id);
  QVERIFY(runner.waitForDone(kTimeoutMs));
  QTest::qWait(50);
  QCOMPARE(stale, 0);
}

void TestJobs::destructorCancelsAndWaits() {
  std::atomic<bool> returned{false}, ranOut{false};
  bool doneCalled = false;
  auto runner = std::make_unique<JobRunner>();
  QSignalSpy progress(runner.get(), &JobRunner::jobProgress);
  runner->start("Forever", untilCancelled(&returned, 20s, &ranOut), [&](QVariant) { doneCalled = true; });
  QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 0, kTimeoutMs);
  QElapsedTimer timer;
  timer.start();
  runner.reset();
  QVERIFY(returned.load());  // the work has returned before the runner is gone
  QVERIFY(!ranOut.load());   // ... because it was cancelled
  qInfo() << "the runner was gone" << timer.elapsed() << "ms after its destruction began";
  if (kerf::testing::timingChecks()) QVERIFY(timer.elapsed() < 1000);
  QTest::qWait(50);
  QVERIFY(!doneCalled);
}

void TestJobs::statusWidgetFollowsJobs() {
  QWidget window;
  JobRunner runner;
  auto* status = new JobStatusWidget(&runner, &window);
  window.resize(400, 60);
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  QVERIFY(status->isHidden());  // idle

  QSignalSpy cancelled(&runner, &JobRunner::jobCancelled);
  const int id = runner.start("Rendering faces…", untilCancelled(nullptr, 2s), {});
  QVERIFY(status->isVisible());
  QCOMPARE(status->shownJob(), id);
  QCOMPARE(status->text(), QStringLiteral("Rendering faces…"));
  QTRY_VERIFY_WITH_TIMEOUT(status->progressPercent() > 0, kTimeoutMs);
  QTest::mouseClick(status->cancelButton(), Qt::LeftButton);
  QCOMPARE(cancelled.count(), 1);
  QVERIFY(status->isHidden());

  // Esc cancels while busy.
  runner.start("Exporting volume…", untilCancelled(nullptr, 2s), {});
  QVERIFY(status->isVisible());
  window.activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(&window));
  QTest::keyClick(&window, Qt::Key_Escape);
  QTRY_COMPARE_WITH_TIMEOUT(cancelled.count(), 2, kTimeoutMs);
  QVERIFY(status->isHidden());

  // Two at once: the newest, with a count.
  runner.start("One", untilCancelled(nullptr, 2s), {});
  const int two = runner.start("Two", untilCancelled(nullptr, 2s), {}, {}, false);
  QCOMPARE(status->shownJob(), two);
  QCOMPARE(status->text(), QStringLiteral("Two (+1)"));
  runner.cancelAll();
  QVERIFY(status->isHidden());
  QVERIFY(runner.waitForDone(kTimeoutMs));
}

void TestJobs::logPanel() {
  LogPanel panel;
  panel.resize(500, 200);
  panel.show();
  QSignalSpy errors(&panel, &LogPanel::errorCountChanged);
  QSignalSpy badge(&panel, &LogPanel::badgeTextChanged);
  JobRunner runner;
  connect(&runner, &JobRunner::message, &panel, &LogPanel::appendMessage);
  runner.start("Loading demo.kerf…",
               [](const Progress&, const JobRunner::Preview&) -> QVariant {
                 throw InputError("missing growth rates");
               },
               {});
  QTRY_COMPARE_WITH_TIMEOUT(panel.errorCount(), 1, kTimeoutMs);
  panel.appendMessage("warning", "the photos are 300 px, the block 40 mm: 7.5 px/mm");
  panel.appendMessage("info", "two\nlines");
  QCOMPARE(panel.lineCount(), 4);  // started, failed, warning, info
  QVERIFY(panel.lineText(0).contains("info") && panel.lineText(0).contains("Loading demo.kerf: started"));
  QVERIFY(panel.lineText(1).contains("error") && panel.lineText(1).contains("missing growth rates"));
  QVERIFY(QRegularExpression("^\\d\\d:\\d\\d:\\d\\d ").match(panel.lineText(1)).hasMatch());  // timestamped
  QVERIFY(panel.lineText(3).contains("two ⏎ lines"));
  const QColor info = panel.lineColor(0), error = panel.lineColor(1), warning = panel.lineColor(2);
  QVERIFY(info != error && error != warning && warning != info);
  QVERIFY(error.red() > 180 && error.green() < 100);
  QCOMPARE(panel.badgeText(), QStringLiteral("1 error"));
  QCOMPARE(errors.count(), 1);
  panel.appendMessage("error", "again");
  QCOMPARE(panel.badgeText(), QStringLiteral("2 errors"));
  QCOMPARE(badge.last().at(0).toString(), QStringLiteral("2 errors"));

  panel.copyToClipboard();
  const QString copied = QApplication::clipboard()->text();
  QVERIFY(copied.contains("missing growth rates") && copied.contains("again"));
  QCOMPARE(copied.count('\n'), 4);

  panel.clear();
  QCOMPARE(panel.lineCount(), 0);
  QCOMPARE(panel.errorCount(), 0);
  QVERIFY(panel.badgeText().isEmpty());
  QCOMPARE(errors.last().at(0).toInt(), 0);
}

QTEST_MAIN(TestJobs)
#include "test_jobs.moc"
