// The editor shell end to end: a demo opens, six faces show in the cross, the photo/rendering toggle
// works, a broken project gives an error without losing the document, and a screenshot is saved.
#include <QAction>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "demo/demo_block.hpp"
#include "faces_view.hpp"
#include "main_window.hpp"
#include "qt_image.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 60000;
}

class TestMainWindow : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void convertsImages();
  void opensDemoWithSixFaces();
  void facesFormTheCross();
  void togglesPhotosAndRendering();
  void malformedProjectShowsError();
  void missingFileShowsError();
  void generatesMissingDemo();
  void savesScreenshot();
  void cleanupTestCase() { window_.reset(); }

 private:
  QMessageBox* visibleMessageBox() const;

  QTemporaryDir dir_;
  QString project_;
  std::unique_ptr<MainWindow> window_;
};

void TestMainWindow::initTestCase() {
  QVERIFY(dir_.isValid());
  DemoOptions options;
  options.facePixels = 64;
  options.samples = 1;
  project_ = QString::fromStdString(writeDemo(dir_.filePath("demo").toStdString(), options).project.string());
  window_ = std::make_unique<MainWindow>(RenderSettings{1.6f, 1});  // 64 px faces, like the photos
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TestMainWindow::convertsImages() {
  Image image(2, 1, 3);
  const float values[] = {1.0f, 0.0f, 0.5f, -1.0f, 2.0f, 0.25f};
  std::copy(std::begin(values), std::end(values), image.pixels.begin());
  const QImage converted = toQImage(image);
  QCOMPARE(converted.size(), QSize(2, 1));
  QCOMPARE(converted.pixelColor(0, 0), QColor(255, 0, 128));
  QCOMPARE(converted.pixelColor(1, 0), QColor(0, 255, 64));  // clamped
  QVERIFY(toQImage(Image{}).isNull());
}

void TestMainWindow::opensDemoWithSixFaces() {
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(project_);
  QVERIFY(window_->isBusy());  // the work runs in the background
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(!window_->isBusy());
  QCOMPARE(window_->windowTitle(), QStringLiteral("demo — Kerf"));

  const FacesView* view = window_->facesView();
  QVERIFY(window_->showingPhotos());
  for (FaceId face : kAllFaces) {
    const QImage& image = view->faces()[faceIndex(face)];
    QVERIFY2(!image.isNull(), qPrintable(QString("face %1 is empty").arg(faceLetter(face))));
    const FaceFrame frame = view->block().face(face);
    QCOMPARE(image.width() * frame.heightMm, image.height() * frame.widthMm);  // right aspect
  }
}

void TestMainWindow::facesFormTheCross() {
  const FacesView* view = window_->facesView();
  const QRectF a = view->faceRect(FaceId::A), b = view->faceRect(FaceId::B), c = view->faceRect(FaceId::C);
  const QRectF d = view->faceRect(FaceId::D), e = view->faceRect(FaceId::E), f = view->faceRect(FaceId::F);
  QVERIFY(view->rect().toRectF().contains(c.united(b).united(d).united(f)));
  QVERIFY(a.width() > 50);  // uses the space it has
  QCOMPARE(b.left(), a.left());
  QCOMPARE(d.left(), a.left());
  QVERIFY(b.bottom() <= a.top() && a.top() - b.bottom() < 5);
  QVERIFY(d.top() >= a.bottom() && d.top() - a.bottom() < 5);
  QCOMPARE(c.top(), a.top());
  QCOMPARE(e.top(), a.top());
  QCOMPARE(f.top(), a.top());
  QVERIFY(c.right() <= a.left() && a.right() <= e.left() && e.right() <= f.left());
}

void TestMainWindow::togglesPhotosAndRendering() {
  QAction* toggle = window_->toggleViewAction();
  QVERIFY(toggle->isEnabled());
  const QImage photoA = window_->facesView()->faces()[0];

  toggle->trigger();
  QVERIFY(!window_->showingPhotos());
  QCOMPARE(toggle->text().remove('&'), QStringLiteral("Show Photos"));
  const QImage renderingA = window_->facesView()->faces()[0];
  QVERIFY(!renderingA.isNull());
  QVERIFY(renderingA != photoA);
  QVERIFY(window_->grab().save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/main_window_rendering.png")));

  toggle->trigger();
  QVERIFY(window_->showingPhotos());
  QCOMPARE(toggle->text().remove('&'), QStringLiteral("Show Model Rendering"));
  QCOMPARE(window_->facesView()->faces()[0], photoA);
}

QMessageBox* TestMainWindow::visibleMessageBox() const {
  for (QMessageBox* box : window_->findChildren<QMessageBox*>()) {
    if (box->isVisible()) return box;
  }
  return nullptr;
}

void TestMainWindow::malformedProjectShowsError() {
  const QString bad = dir_.filePath("malformed.kerf");
  QFile file(bad);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write("{ \"format\": \"kerf-project\", \"version\": ");
  file.close();

  QSignalSpy failed(window_.get(), &MainWindow::documentFailed);
  window_->openDocument(bad);
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kTimeoutMs);
  QVERIFY(!window_->lastError().isEmpty());
  QMessageBox* box = visibleMessageBox();
  QVERIFY(box);
  QCOMPARE(box->text(), window_->lastError());
  box->accept();
  QTRY_VERIFY(!visibleMessageBox());

  // The demo is still the document and still usable.
  QVERIFY(!window_->isBusy());
  QCOMPARE(window_->documentName(), QStringLiteral("demo"));
  QVERIFY(window_->facesView()->hasFaces());
  QVERIFY(window_->toggleViewAction()->isEnabled());
}

void TestMainWindow::missingFileShowsError() {
  QSignalSpy failed(window_.get(), &MainWindow::documentFailed);
  window_->openDocument(dir_.filePath("nowhere.kerf"));
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kTimeoutMs);
  QVERIFY2(window_->lastError().contains("nowhere.kerf"), qPrintable(window_->lastError()));
  QMessageBox* box = visibleMessageBox();
  QVERIFY(box);
  box->accept();
  QCOMPARE(window_->documentName(), QStringLiteral("demo"));
}

void TestMainWindow::generatesMissingDemo() {
  MainWindow window(RenderSettings{0.8f, 1});
  QSignalSpy ready(&window, &MainWindow::documentReady);
  DemoOptions options;
  options.facePixels = 32;
  options.samples = 1;
  window.openDemo(dir_.filePath("cache/demo"), options);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(QFileInfo::exists(dir_.filePath("cache/demo/demo.kerf")));
  QCOMPARE(window.facesView()->faces()[0].width(), 32);
}

void TestMainWindow::savesScreenshot() {
  const QString path = QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/main_window.png");
  QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
  QVERIFY(window_->grab().save(path));
  QVERIFY(QFileInfo(path).size() > 0);
}

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
