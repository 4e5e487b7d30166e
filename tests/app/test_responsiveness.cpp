// The editor stays responsive during long jobs (issue 8): a timer on the GUI thread measures the longest
// gap between its ticks (the longest event-loop stall) while a growth-field fit and an export run at the
// same time; and closing the window during those jobs cancels them and returns promptly.
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "demo/demo_block.hpp"
#include "export/export_job.hpp"
#include "gl/surface_format.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 120000;
// The bound the test enforces. The stalls measured on a shared 2-core VM are in docs/reliability.md;
// the bound leaves room for a loaded CI machine and still catches work done on the GUI thread.
constexpr qint64 kMaxStallMs = 1000;

// Ticks every 5 ms on the GUI thread; the longest interval between ticks is the longest stall.
class StallProbe : public QObject {
 public:
  StallProbe() {
    timer_.setInterval(5);
    connect(&timer_, &QTimer::timeout, this, [this] { longest_ = std::max(longest_, clock_.restart()); });
    clock_.start();
    timer_.start();
  }
  qint64 longestMs() const { return longest_; }

 private:
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 longest_ = 0;
};
}  // namespace

class TestResponsiveness : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void fitAndExportKeepTheEventLoopResponsive();
  void closingDuringJobsCancelsThem();

 private:
  std::unique_ptr<MainWindow> openDemo();
  QTemporaryDir dir_;
  QString project_;
};

void TestResponsiveness::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  DemoOptions options;
  options.facePixels = 64;
  options.samples = 1;
  project_ = QString::fromStdString(writeDemo(dir_.filePath("demo").toStdString(), options).project.string());
}

std::unique_ptr<MainWindow> TestResponsiveness::openDemo() {
  auto window = std::make_unique<MainWindow>(RenderSettings{1.6f, 1});
  window->setAskBeforeDiscarding(false);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get())) return nullptr;
  QSignalSpy ready(window.get(), &MainWindow::documentReady);
  window->openDocument(project_);
  if (!ready.wait(kTimeoutMs)) return nullptr;
  QSignalSpy detected(window.get(), &MainWindow::ringsDetected);
  window->detectRingsAction()->trigger();
  if (!detected.wait(kTimeoutMs)) return nullptr;
  return window;
}

void TestResponsiveness::fitAndExportKeepTheEventLoopResponsive() {
  auto window = openDemo();
  QVERIFY(window);
  QTRY_VERIFY_WITH_TIMEOUT(!window->isBusy(), kTimeoutMs);
  QSignalSpy fitted(window.get(), &MainWindow::growthFieldFitted);
  QSignalSpy fitFailed(window.get(), &MainWindow::ringJobFailed);
  QSignalSpy exported(window.get(), &MainWindow::exportFinished);
  QSignalSpy exportFailed(window.get(), &MainWindow::exportFailed);
  ExportRequest request;
  request.out = dir_.filePath("growth.nrrd").toStdString();
  request.resolution = 96;

  QElapsedTimer wall;
  wall.start();
  const StallProbe probe;
  window->fitGrowthAction()->trigger();
  window->startExport(request);
  QTRY_VERIFY_WITH_TIMEOUT(fitted.count() + fitFailed.count() > 0, kTimeoutMs);
  QTRY_VERIFY_WITH_TIMEOUT(exported.count() + exportFailed.count() > 0, kTimeoutMs);
  QTRY_VERIFY_WITH_TIMEOUT(!window->isBusy(), kTimeoutMs);
  QTest::qWait(50);  // the results applied and drawn
  QVERIFY2(fitFailed.isEmpty(), qPrintable(window->lastError()));
  QVERIFY2(exportFailed.isEmpty(), qPrintable(window->lastError()));
  qInfo("fit + export: %lld ms; longest event-loop stall %lld ms", static_cast<long long>(wall.elapsed()),
        static_cast<long long>(probe.longestMs()));
  QVERIFY2(probe.longestMs() < kMaxStallMs, qPrintable(QString::number(probe.longestMs()) + " ms"));
}

void TestResponsiveness::closingDuringJobsCancelsThem() {
  auto window = openDemo();
  QVERIFY(window);
  QTRY_VERIFY_WITH_TIMEOUT(!window->isBusy(), kTimeoutMs);
  ExportRequest request;
  request.out = dir_.filePath("closing.nrrd").toStdString();
  request.resolution = 160;
  window->fitGrowthAction()->trigger();
  window->startExport(request);
  QVERIFY(window->isBusy());
  QTest::qWait(100);  // both jobs are running

  QElapsedTimer closing;
  closing.start();
  QVERIFY(window->close());
  window.reset();  // JobRunner: stop requested, workers joined
  qInfo("closed during a fit and an export in %lld ms", static_cast<long long>(closing.elapsed()));
  QVERIFY2(closing.elapsed() < 5000, qPrintable(QString::number(closing.elapsed()) + " ms"));
  QVERIFY(!QFile::exists(dir_.filePath("closing.nrrd")));  // cancelled, not finished, nothing half-written
  const QStringList left = QDir(dir_.path()).entryList({"*.tmp*"}, QDir::Files | QDir::Hidden);
  QVERIFY2(left.isEmpty(), qPrintable(left.join(", ")));
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  qputenv("KERF_DEFAULT_LAYOUT", "1");
  TestResponsiveness test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_responsiveness.moc"
