// The editor's event loop stays responsive while long jobs run (ring detection, texture inference, photo
// import, the photo-true surfaces made while the cut plane moves, and a growth-field fit and a volume
// export at the same time), and closing the window during a job
// cancels it cleanly: the window goes away at once, the fit is not applied and the export leaves no file
// behind (issue 8).
//
// The stall probe is a 5 ms timer on the GUI thread: the longest gap between two of its ticks is the
// longest time the event loop did not get round to user input. It includes the GUI thread's own work
// while the jobs run: applying previews, repainting the faces and the 3D view (Mesa llvmpipe, on the same
// two cores as the jobs).
#include <QDialogButtonBox>
#include <QDir>
#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <algorithm>

#include "appearance_controller.hpp"
#include "cut_view.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"
#include "photo_import_dialog.hpp"
#include "quick_texture_options.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 120000;
// The longest stall allowed. Single software-rendered 3D frames take up to ~0.4 s on a loaded 2-core
// machine (docs/performance.md); the views refine in bands so that no single turn takes that long,
// and the jobs never run on the GUI thread. A blocking fit or export would stall for seconds.
#if defined(__SANITIZE_ADDRESS__)
constexpr qint64 kSlowdown =
    2;  // under ASan everything, the GUI thread's own work too, is about twice as slow
#else
constexpr qint64 kSlowdown = 1;
#endif
constexpr qint64 kMaxStallMs = 1000 * kSlowdown;
// The import does little on the GUI thread (small previews), so it is held to less: 113-123 ms measured at
// load 4.5 (277-325 ms under ASan); with its photos read on Qt's global pool (the bug background_pool.hpp
// explains) 956-1117 ms, which the general bound caught only half the time.
constexpr qint64 kMaxImportStallMs = 500 * kSlowdown;

class StallProbe {
 public:
  StallProbe() {
    timer_.setInterval(5);
    QObject::connect(&timer_, &QTimer::timeout, [this] {
      const qint64 now = clock_.elapsed();
      longest_ = std::max(longest_, now - last_);
      last_ = now;
      ++ticks_;
    });
  }
  void start() {
    clock_.start();
    last_ = 0;
    longest_ = 0;
    ticks_ = 0;
    timer_.start();
  }
  void stop() { timer_.stop(); }
  qint64 longestMs() const { return longest_; }
  qint64 elapsedMs() const { return clock_.elapsed(); }
  int ticks() const { return ticks_; }

 private:
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 last_ = 0, longest_ = 0;
  int ticks_ = 0;
};

// A phone photo of a face: `size` px, the face a lighter quadrilateral with rings on a dark table.
QImage phonePhoto(QSize size, int seed) {
  QImage photo(size, QImage::Format_RGB32);
  photo.fill(QColor(40, 38, 35));
  QPainter painter(&photo);
  painter.setRenderHint(QPainter::Antialiasing);
  const QRectF face(size.width() * 0.15, size.height() * 0.15, size.width() * 0.7, size.height() * 0.7);
  painter.setBrush(QColor(200, 160, 110));
  painter.drawRect(face);
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(QColor(150, 100, 60), size.width() / 300.0));
  for (int ring = 1; ring < 40; ++ring)
    painter.drawEllipse(face.center() + QPointF(seed * 30.0, -seed * 20.0), ring * face.width() / 30.0,
                        ring * face.height() / 34.0);
  return photo;
}

bool folderHasNoFiles(const QString& folder) {
  return QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot).isEmpty();
}
}  // namespace

class TestResponsiveness : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void fitAndExportKeepTheEventLoopResponsive();
  void detectionAndTextureInferenceKeepTheEventLoopResponsive();
  void photoImportKeepsTheEventLoopResponsive();
  void photoTrueAppearanceKeepsTheEventLoopResponsive();
  void closingDuringAJobCancelsIt();

 private:
  std::unique_ptr<MainWindow> openDemo(const QString& name);

  QTemporaryDir dir_;
};

void TestResponsiveness::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());  // never the user's own folder
}

std::unique_ptr<MainWindow> TestResponsiveness::openDemo(const QString& name) {
  return kerf::testing::openDemoWindow(dir_.filePath(name), 128, {1280, 800}, kTimeoutMs);
}

void TestResponsiveness::fitAndExportKeepTheEventLoopResponsive() {
  auto window = openDemo("demo_fit");
  QVERIFY(window);
  QSignalSpy detected(window.get(), &MainWindow::ringsDetected);
  QSignalSpy ringFailed(window.get(), &MainWindow::ringJobFailed);
  window->detectRingsAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() + ringFailed.count() > 0, kTimeoutMs);
  QVERIFY2(ringFailed.isEmpty(), qPrintable(window->lastError()));

  QSignalSpy fitted(window.get(), &MainWindow::growthFieldFitted);
  QSignalSpy exported(window.get(), &MainWindow::exportFinished);
  QSignalSpy exportFailed(window.get(), &MainWindow::exportFailed);
  ExportRequest request;
  request.out = dir_.filePath("colour.nrrd").toStdString();
  request.quantity = VolumeQuantity::Color;
  request.resolution = 112;

  StallProbe probe;
  probe.start();
  window->fitGrowthAction()->trigger();
  window->exports()->startExport(request);
  QVERIFY(window->isBusy());
  QTRY_VERIFY_WITH_TIMEOUT(
      fitted.count() + ringFailed.count() > 0 && exported.count() + exportFailed.count() > 0, 4 * kTimeoutMs);
  probe.stop();
  QVERIFY2(ringFailed.isEmpty(), qPrintable(window->lastError()));
  QVERIFY2(exportFailed.isEmpty(), qPrintable(window->lastError()));
  QVERIFY(QFileInfo::exists(dir_.filePath("colour.nrrd")));
  qInfo("fit + export: %lld ms, %d probe ticks, longest event-loop stall %lld ms (allowed %lld ms)",
        probe.elapsedMs(), probe.ticks(), probe.longestMs(), kMaxStallMs);
  QVERIFY2(probe.longestMs() < kMaxStallMs,
           qPrintable(QString("the event loop stalled for %1 ms").arg(probe.longestMs())));
}

void TestResponsiveness::detectionAndTextureInferenceKeepTheEventLoopResponsive() {
  auto window = openDemo("demo_texture");
  QVERIFY(window);
  QSignalSpy detected(window.get(), &MainWindow::ringsDetected);
  QSignalSpy ringFailed(window.get(), &MainWindow::ringJobFailed);
  StallProbe probe;
  probe.start();
  window->detectRingsAction()->trigger();
  QVERIFY(window->isBusy());
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() + ringFailed.count() > 0, kTimeoutMs);
  probe.stop();
  QVERIFY2(ringFailed.isEmpty(), qPrintable(window->lastError()));
  qInfo("ring detection: %lld ms, longest event-loop stall %lld ms", probe.elapsedMs(), probe.longestMs());
  QVERIFY2(probe.longestMs() < kMaxStallMs,
           qPrintable(QString("the event loop stalled for %1 ms during detection").arg(probe.longestMs())));

  window->texture()->setTextureOptions(kerf::testing::quickTextureOptions());
  QSignalSpy inferred(window.get(), &MainWindow::textureInferred);
  QSignalSpy previewed(window.get(), &MainWindow::texturePreviewed);
  QSignalSpy textureFailed(window.get(), &MainWindow::textureJobFailed);
  probe.start();
  window->inferTextureAction()->trigger();
  QVERIFY(window->isBusy());
  QTRY_VERIFY_WITH_TIMEOUT(inferred.count() + textureFailed.count() > 0, 2 * kTimeoutMs);
  probe.stop();
  QVERIFY2(textureFailed.isEmpty(), qPrintable(window->lastError()));
  QVERIFY(previewed.count() >= 1);  // the previews were applied on the GUI thread while it ran
  qInfo("texture inference: %lld ms, %lld previews, longest event-loop stall %lld ms", probe.elapsedMs(),
        qint64(previewed.count()), probe.longestMs());
  QVERIFY2(probe.longestMs() < kMaxStallMs,
           qPrintable(
               QString("the event loop stalled for %1 ms during texture inference").arg(probe.longestMs())));
}

void TestResponsiveness::photoImportKeepsTheEventLoopResponsive() {
  // Six 17-megapixel phone photos, one per face: decoding them and warping them onto the faces is the
  // work; the dialog reads them in the background and the import writes the faces in the background.
  const QString photos = dir_.filePath("photos");
  QVERIFY(QDir().mkpath(photos));
  QStringList files;
  for (int i = 0; i < 6; ++i) {
    const QString file = photos + QString("/%1_face.jpg").arg(QChar('A' + i));
    QVERIFY(phonePhoto({4800, 3600}, i).save(file, "JPG", 90));
    files << file;
  }
  auto window = openDemo("demo_import");
  QVERIFY(window);
  QSignalSpy imported(window.get(), &MainWindow::photosImported);
  StallProbe probe;
  probe.start();
  window->files()->importPhotos(files);
  auto* dialog = window->findChild<PhotoImportDialog*>();
  QVERIFY(dialog);
  dialog->setAskBeforeReplacing(false);
  QTRY_VERIFY_WITH_TIMEOUT(dialog->photoCount() == 6 && !dialog->isLoading(), kTimeoutMs);
  const qint64 loadedMs = probe.elapsedMs(), loadStall = probe.longestMs();
  dialog->setBlockSize({40, 40, 40});
  dialog->setPxPerMm(10);
  dialog->setOutputFolder(dir_.filePath("imported_faces"));
  QTest::qWait(200);  // the live preview of the six faces
  auto* buttons = dialog->findChild<QDialogButtonBox*>();
  QVERIFY(buttons);
  QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
  QTRY_VERIFY_WITH_TIMEOUT(imported.count() > 0, kTimeoutMs);
  probe.stop();
  QVERIFY(QFileInfo::exists(dir_.filePath("imported_faces/F_col.png")));
  qInfo(
      "photo import: photos read in %lld ms (longest stall %lld ms), all done in %lld ms, longest "
      "event-loop stall %lld ms",
      loadedMs, loadStall, probe.elapsedMs(), probe.longestMs());
  QVERIFY2(probe.longestMs() < kMaxImportStallMs,
           qPrintable(QString("the event loop stalled for %1 ms during the import").arg(probe.longestMs())));
}

// Texture > Photo-true Appearance: the guidance, the cut and the six faces are made in the background and
// land as pictures on the GUI thread (textures, the faces view), while the user moves the cut plane.
void TestResponsiveness::photoTrueAppearanceKeepsTheEventLoopResponsive() {
  auto window = openDemo("demo_photo_true");
  QVERIFY(window);
  AppearanceController* appearance = window->appearance();
  QSignalSpy faces(appearance, &AppearanceController::facesMade);
  window->document()->setCutEnabled(true);
  StallProbe probe;
  probe.start();
  appearance->photoTrueAction()->trigger();
  for (int step = 0; step < 5; ++step) {  // the plane dragged while the surfaces are being made
    QTest::qWait(200);
    window->document()->editCutPlane({float(step), 10.0f * step, 20.0f}, step == 4);
  }
  QTRY_VERIFY_WITH_TIMEOUT(faces.count() > 0 && !appearance->isWorking(), 2 * kTimeoutMs);
  probe.stop();
  QVERIFY(window->cutView()->showsCutAppearance());
  qInfo("photo-true appearance: %lld ms, longest event-loop stall %lld ms", probe.elapsedMs(),
        probe.longestMs());
  QVERIFY2(probe.longestMs() < kMaxStallMs,
           qPrintable(QString("the event loop stalled for %1 ms while the photo-true surfaces were made")
                          .arg(probe.longestMs())));
}

void TestResponsiveness::closingDuringAJobCancelsIt() {
  auto window = openDemo("demo_close");
  QVERIFY(window);
  QSignalSpy detected(window.get(), &MainWindow::ringsDetected);
  window->detectRingsAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() > 0, kTimeoutMs);
  const QString folder = dir_.filePath("close_export");
  QVERIFY(QDir().mkpath(folder));
  ExportRequest request;
  request.out = (folder + "/colour.nrrd").toStdString();
  request.quantity = VolumeQuantity::Color;
  request.resolution = 400;  // 64 M voxels: far longer than the test waits
  QSignalSpy exported(window.get(), &MainWindow::exportFinished);
  QSignalSpy fitted(window.get(), &MainWindow::growthFieldFitted);
  const WoodParameters before = window->document()->project().params;
  window->fitGrowthAction()->trigger();
  const int id = window->exports()->startExport(request);
  QTRY_VERIFY_WITH_TIMEOUT(window->jobs()->progressOf(id) > 0.0, kTimeoutMs);  // both under way
  QCOMPARE(window->jobs()->runningJobs().size(), 2);

  QElapsedTimer closing;
  closing.start();
  QVERIFY(window->close());
  QVERIFY(!window->isVisible());
  QVERIFY2(!window->jobs()->isBusy(), "closing the window did not cancel the running jobs");
  QVERIFY(window->document()->project().params == before);  // the fit was not applied
  window.reset();  // the job runner waits for the cancelled work to return
  const qint64 closeMs = closing.elapsed();
  qInfo("closed with a fit and an export running in %lld ms", closeMs);
  QVERIFY2(closeMs < 5000, qPrintable(QString("closing took %1 ms").arg(closeMs)));
  QCOMPARE(exported.count(), 0);
  QCOMPARE(fitted.count(), 0);
  // Written atomically: neither the target nor a temporary file is left in the folder.
  QVERIFY2(folderHasNoFiles(folder), qPrintable(QDir(folder).entryList(QDir::Files).join(", ")));
}

QTEST_MAIN(TestResponsiveness)
#include "test_responsiveness.moc"
