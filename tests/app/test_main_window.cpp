// The editor shell end to end: a demo opens, six faces show in the cross, the photo/rendering toggle
// works, a broken project gives an error without losing the document, and a screenshot is saved.
#include <QAction>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <QCheckBox>
#include <QSlider>
#include <QUndoStack>

#include "autosave.hpp"
#include "cut_gizmo.hpp"
#include "cut_plane_controls.hpp"
#include "cut_view.hpp"
#include "demo/demo_block.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "field/growth_field.hpp"
#include "gpu/surface_format.hpp"
#include "image_change.hpp"
#include "job_runner.hpp"
#include "log_panel.hpp"
#include "main_window.hpp"
#include "parameter_panel.hpp"
#include "qt_image.hpp"
#include "viewport3d.hpp"
#include "window_grab.hpp"

using namespace kerf;
using kerf::testing::changedShare;

namespace {
// A hang guard for each wait on the editor's signals, not a measure: the whole test takes about 60 s under
// ASan + UBSan on 2 cores (docs/reliability.md), so the bound leaves a slower runner room.
constexpr int kTimeoutMs = 300000;

QPoint toPoint(glm::vec3 px) {
  return {static_cast<int>(std::lround(px.x)), static_cast<int>(std::lround(px.y))};
}

using testing::artifact;
}  // namespace

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
  void sliderChangesTheViews();
  void draggingTheCutPlaneChangesTheCutPanel();
  void undoRestores();
  void saveAndReopenRoundTrip();
  void recoversAutosavedWorkAfterACrash();
  void detectsRingsAndShowsContours();
  void fitsGrowthFieldAsOneUndoStep();
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
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());  // never the user's own folder
  DemoOptions options;
  options.facePixels = 64;
  options.samples = 1;
  project_ = QString::fromStdString(writeDemo(dir_.filePath("demo").toStdString(), options).project.string());
  window_ = std::make_unique<MainWindow>(RenderSettings{1.6f, 1});  // 64 px faces, like the photos
  window_->setAskBeforeDiscarding(false);
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
  QCOMPARE(window_->windowTitle().remove(QStringLiteral("[*]")), QStringLiteral("demo — Kerf"));
  QVERIFY(!window_->isWindowModified());

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
  QTRY_VERIFY_WITH_TIMEOUT(!visibleMessageBox(), kTimeoutMs);

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

void TestMainWindow::sliderChangesTheViews() {
  Viewport3D* viewport = window_->viewport();
  QTRY_VERIFY_WITH_TIMEOUT(viewport->ready(), kTimeoutMs);
  viewport->refineNow();
  const QImage block = viewport->grabFramebuffer();
  window_->toggleViewAction()->trigger();  // show the model's faces
  QVERIFY(!window_->showingPhotos());
  const QImage faceA = window_->facesView()->faces()[0];

  // The "Average ring width" slider, moved with the keyboard as a user would.
  const int row = static_cast<int>(*parameterIndex("growth.ring_width"));
  QSlider* slider = window_->parameterPanel()->row(row)->findChild<QSlider*>();
  QVERIFY(slider);
  const float before = window_->document()->project().params.ringWidth;
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  slider->setFocus();
  QTest::keyClick(slider, Qt::Key_PageUp);
  QVERIFY(window_->document()->project().params.ringWidth > before);
  QCOMPARE(window_->document()->undoStack()->count(), 1);
  QVERIFY(window_->isWindowModified());

  QTRY_VERIFY_WITH_TIMEOUT(rendered.count() >= 1, kTimeoutMs);
  QVERIFY2(changedShare(window_->facesView()->faces()[0], faceA) > 0.05, "faces did not follow the slider");
  viewport->refineNow();
  const QImage blockAfter = viewport->grabFramebuffer();
  QVERIFY2(changedShare(blockAfter, block) > 0.02, "the 3D view did not follow the slider");
  QVERIFY(blockAfter.save(artifact("main_window_slider_3d")));
  window_->toggleViewAction()->trigger();
}

void TestMainWindow::draggingTheCutPlaneChangesTheCutPanel() {
  // Show the cut with the controls' checkbox, as a user would.
  QCheckBox* show = nullptr;
  for (QCheckBox* box : window_->cutControls()->findChildren<QCheckBox*>())
    if (box->text().remove('&') == QStringLiteral("Show cut")) show = box;
  QVERIFY(show);
  QVERIFY(show->isVisible());
  // The demo opens with the cut shown: hide it, then show it again.
  QVERIFY(window_->document()->cutEnabled());
  QTest::mouseClick(show, Qt::LeftButton, {}, QPoint(8, show->height() / 2));  // on the box itself
  QTRY_VERIFY_WITH_TIMEOUT(!window_->document()->cutEnabled(), kTimeoutMs);
  QVERIFY(!window_->viewport()->cutEnabled());
  QTest::mouseClick(show, Qt::LeftButton, {}, QPoint(8, show->height() / 2));
  QTRY_VERIFY_WITH_TIMEOUT(window_->document()->cutEnabled(), kTimeoutMs);
  QVERIFY(window_->viewport()->cutEnabled());
  window_->document()->editCutPlane({5.0f, 0.0f, 0.0f}, true);  // facing +x: the default view sees it
  const int steps = window_->document()->undoStack()->count();
  CutView* cutView = window_->cutView();
  const QImage cutBefore = cutView->grabFramebuffer();

  Viewport3D* viewport = window_->viewport();
  viewport->grabFramebuffer();
  const CutGizmo& gizmo = viewport->gizmo();
  const OrbitCamera& camera = viewport->camera();
  glm::vec3 grab(0.0f);
  bool found = false;
  for (const glm::vec3& corner : gizmo.polygon())
    for (float t : {0.8f, 0.65f, 0.5f}) {
      const glm::vec3 p = gizmo.pivot() + t * (corner - gizmo.pivot());
      const glm::vec3 px = camera.project(p);
      if (!found && gizmo.pick(camera, {px.x, px.y}) == CutGizmo::Handle::Surface) grab = p, found = true;
    }
  QVERIFY2(found, "no free spot on the cut surface");
  const glm::vec3 p0 = camera.project(grab),
                  p1 = camera.project(grab - glm::vec3(1, 0, 0));  // into the block
  const glm::vec2 dir = glm::normalize(glm::vec2(p1) - glm::vec2(p0));
  const QPoint start = toPoint(p0);
  QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, start);
  for (int i = 1; i <= 6; ++i)
    QTest::mouseMove(viewport, start + QPoint(std::lround(dir.x * 6 * i), std::lround(dir.y * 6 * i)));
  QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier,
                      start + QPoint(std::lround(dir.x * 36), std::lround(dir.y * 36)));

  const CutPlaneSetting moved = window_->document()->cutPlane();
  QVERIFY2(moved.offsetMm < 4.0f, qPrintable(QString("offset %1").arg(moved.offsetMm)));
  QCOMPARE(window_->document()->undoStack()->count(), steps + 1);  // the whole drag is one step
  QCOMPARE(window_->cutControls()->setting(), moved);
  QTRY_VERIFY_WITH_TIMEOUT(changedShare(cutView->grabFramebuffer(), cutBefore) > 0.02, 30000);
  QVERIFY(cutView->grabFramebuffer().save(artifact("main_window_cut_panel")));
}

void TestMainWindow::undoRestores() {
  QUndoStack* undo = window_->document()->undoStack();
  const CutPlaneSetting placed{5.0f, 0.0f, 0.0f};
  window_->undoAction()->trigger();  // the drag
  QCOMPARE(window_->document()->cutPlane(), placed);
  QCOMPARE(window_->cutControls()->setting(), placed);
  QCOMPARE(window_->viewport()->cutPlane(), placed);
  window_->undoAction()->trigger();  // placing the plane
  window_->undoAction()->trigger();  // the ring-width slider
  QCOMPARE(undo->index(), 0);
  QCOMPARE(window_->document()->project().params, demoProject().params);
  QCOMPARE(window_->parameterPanel()->parameters(), demoProject().params);
  QVERIFY(!window_->isWindowModified() ||
          window_->document()->cutEnabled());  // showing the cut is a view change
  window_->redoAction()->trigger();
  QVERIFY(window_->document()->project().params.ringWidth > demoProject().params.ringWidth);
}

void TestMainWindow::saveAndReopenRoundTrip() {
  window_->document()->editCutPlane({-3.0f, 30.0f, 15.0f}, true);
  const Project saved = window_->document()->project();
  const QString path = dir_.filePath("saved/block.kerf");
  QVERIFY(QDir().mkpath(dir_.filePath("saved")));
  QVERIFY(window_->saveAs(path));
  QVERIFY(!window_->isWindowModified());
  QCOMPARE(window_->documentName(), QStringLiteral("block"));

  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(path);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  const Project& reopened = window_->document()->project();
  QCOMPARE(reopened.params, saved.params);
  QCOMPARE(window_->document()->cutPlane(), (CutPlaneSetting{-3.0f, 30.0f, 15.0f}));
  QCOMPARE(window_->document()->cutEnabled(), saved.cutEnabled);
  for (int i = 0; i < 6; ++i) QCOMPARE(reopened.facePhotos[i], saved.facePhotos[i]);
  QCOMPARE(window_->document()->filePath(), QFileInfo(path).absoluteFilePath());
  QCOMPARE(window_->document()->undoStack()->count(), 0);
}

void TestMainWindow::recoversAutosavedWorkAfterACrash() {
  const std::size_t ring = *parameterIndex("growth.ring_width");
  QString leftover;
  {
    MainWindow crashed(RenderSettings{0.8f, 1});
    QSignalSpy ready(&crashed, &MainWindow::documentReady);
    crashed.openDocument(project_);
    QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
    crashed.document()->editParameter(ring, {5.5f, 0, 0}, true);
    crashed.autosave()->saveNow();
    leftover = crashed.autosave()->currentFile();
    QVERIFY(QFile::exists(leftover));
    // Destroyed without closing, as in a crash: the copy stays.
  }
  QVERIFY(QFile::exists(leftover));
  MainWindow next(RenderSettings{0.8f, 1});
  next.setAskBeforeDiscarding(false);
  QVERIFY(next.autosave()->leftovers().contains(QFileInfo(leftover).absoluteFilePath()));
  QSignalSpy ready(&next, &MainWindow::documentReady);
  next.recover(leftover);
  QCOMPARE(next.document()->project().params.ringWidth, 5.5f);
  QVERIFY(next.document()->isModified());
  QCOMPARE(next.document()->filePath(), QFileInfo(project_).absoluteFilePath());  // Save goes back there
  QVERIFY(next.document()->hasPhotos());
  QVERIFY(!QFile::exists(leftover));
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
}

// Rings ▸ Detect Rings on a demo with 256 px photos (Mokume's resolution): contours on several faces,
// drawn over the faces while View ▸ Show Ring Contours is on.
void TestMainWindow::detectsRingsAndShowsContours() {
  DemoOptions options;
  options.facePixels = 256;
  options.samples = 1;
  const QString project =
      QString::fromStdString(writeDemo(dir_.filePath("demo256").toStdString(), options).project.string());
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(project);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(window_->showingPhotos());
  QVERIFY(!window_->rings()->ringDetection());
  QVERIFY(!window_->showContoursAction()->isEnabled());

  QSignalSpy detected(window_.get(), &MainWindow::ringsDetected);
  QSignalSpy failed(window_.get(), &MainWindow::ringJobFailed);
  window_->detectRingsAction()->trigger();
  QVERIFY(window_->isBusy());  // a background job
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() + failed.count() > 0, kTimeoutMs);
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  const auto detection = window_->rings()->ringDetection();
  QVERIFY(detection);
  QCOMPARE(detection->facesDetected, 6);
  int facesWithContours = 0;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    QCOMPARE(detection->arl[i].width, window_->document()->photos()[i].width());
    facesWithContours += detection->contours[i].size() >= 2;
  }
  QVERIFY2(facesWithContours >= 4, qPrintable(QString("contours on %1 faces").arg(facesWithContours)));
  // The contours became the document's detected ring traces (drawn by the annotation layer).
  QVERIFY(!window_->document()->annotations().traces.empty());
  QCOMPARE(window_->document()->annotations().traces.front().origin, TraceOrigin::Detected);
  QVERIFY(window_->showContoursAction()->isEnabled());
  QVERIFY(window_->showContoursAction()->isChecked());

  // The overlay draws: the faces view changes when the contours are hidden, and comes back.
  FacesView* view = window_->facesView();
  QTest::qWait(50);
  const QImage shown = view->grab().toImage();
  window_->showContoursAction()->trigger();
  QVERIFY(!view->overlayVisible());
  const QImage hidden = view->grab().toImage();
  const double share = changedShare(shown, hidden);
  QVERIFY2(share > 0.01, qPrintable(QString("only %1 of the pixels changed").arg(share)));
  window_->showContoursAction()->trigger();
  QVERIFY(view->overlayVisible());
  QCOMPARE(changedShare(shown, view->grab().toImage()), 0.0);
  QVERIFY(QDir().mkpath(KERF_TEST_ARTIFACTS_DIR));
  QVERIFY(shown.save(artifact("rings_faces")));
  QVERIFY(grabWindowWithGl(window_.get()).save(artifact("rings_window")));
  // A larger view of the same, to judge how the contours sit on the rings.
  FacesView large;
  large.resize(1400, 1050);
  large.setBlock(window_->document()->project().block);
  large.setPhotos(window_->document()->photos());
  large.setOverlayPolylines(contourPolylines(*detection), detectionSizes(*detection));
  QVERIFY(large.grab().toImage().save(artifact("rings_faces_large")));
}

// Rings ▸ Fit Growth Field on the detected rings: the growth parameters and rates change in one undo
// step, and undo restores both.
void TestMainWindow::fitsGrowthFieldAsOneUndoStep() {
  QVERIFY(window_->rings()->ringDetection());
  Document* document = window_->document();
  const WoodParameters before = document->project().params;
  const bool hadRates = document->project().rates.has_value();
  const int steps = document->undoStack()->count();
  QSignalSpy fitted(window_.get(), &MainWindow::growthFieldFitted);
  QSignalSpy failed(window_.get(), &MainWindow::ringJobFailed);
  // Cancel (the status bar's button, Esc) leaves the document as it was.
  window_->fitGrowthAction()->trigger();
  QVERIFY(window_->isBusy());
  window_->jobs()->cancelAll();
  QCOMPARE(failed.count(), 1);
  QVERIFY(window_->jobs()->waitForDone(kTimeoutMs));
  QTest::qWait(100);
  QCOMPARE(fitted.count(), 0);
  QCOMPARE(document->undoStack()->count(), steps);
  QVERIFY(document->project().params == before);
  failed.clear();

  QSignalSpy previewed(window_.get(), &MainWindow::fitPreviewed);
  window_->fitGrowthAction()->trigger();
  QVERIFY(window_->isBusy());
  QTRY_VERIFY_WITH_TIMEOUT(fitted.count() + failed.count() > 0, 4 * kTimeoutMs);
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  // Live preview: the undeformed field after the pith stage, then the fitted one, before it is applied.
  QVERIFY2(previewed.count() >= 2, qPrintable(QString("%1 previews").arg(previewed.count())));
  // Every fitted ring trace is drawn over the faces, coloured by its residual; hiding them changes the view.
  FacesView* view = window_->facesView();
  QVERIFY(view->hasOverlay());
  int coloured = 0;
  for (const auto& colours : view->overlayColors()) coloured += static_cast<int>(colours.size());
  QCOMPARE(coloured, static_cast<int>(document->annotations().traces.size()));
  QVERIFY(window_->showResidualsAction()->isEnabled());
  QTest::qWait(50);
  const QImage withResiduals = view->grab().toImage();
  QVERIFY(withResiduals.save(artifact("fit_residuals")));
  window_->showResidualsAction()->trigger();
  QVERIFY(!view->overlayVisible());
  QVERIFY(changedShare(withResiduals, view->grab().toImage()) > 0.005);
  window_->showResidualsAction()->trigger();
  QCOMPARE(document->undoStack()->count(), steps + 1);
  QCOMPARE(document->undoStack()->undoText(), QStringLiteral("Fit growth field"));
  const WoodParameters after = document->project().params;
  QVERIFY(after != before);
  QVERIFY(after.pithOrigin != before.pithOrigin || after.pithTilt != before.pithTilt);
  QVERIFY(after.ringWidth > 0.2f && after.ringWidth < 20.0f);
  QVERIFY(document->project().rates.has_value());
  QCOMPARE(document->model()->field().rates().rates, document->project().rates->rates);
  // The log says what the fit found and how long it took.
  const QString log = window_->log()->text();
  for (const char* expected : {"pith: O = (", ", V = (", "iso-contour loss", "ambiguity (Mokume B.1)",
                               "ring traces: ", "colours (Mokume A.2.3)", "time: contours"})
    QVERIFY2(log.contains(QLatin1String(expected)), expected);

  window_->undoAction()->trigger();
  QVERIFY(document->project().params == before);
  QCOMPARE(document->project().rates.has_value(), hadRates);
  window_->redoAction()->trigger();
  QVERIFY(document->project().params == after);
  QVERIFY(window_->rings()->ringDetection());  // the detection stays with the photos
}

void TestMainWindow::savesScreenshot() {
  const QString path = QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/main_window.png");
  QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
  QVERIFY(grabWindowWithGl(window_.get()).save(path));
  QVERIFY(QFileInfo(path).size() > 0);
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();  // as the editor does
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  // The default window layout, whatever an earlier run saved: pixel positions in the tests depend on it.
  qputenv("KERF_DEFAULT_LAYOUT", "1");
  TestMainWindow test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_main_window.moc"
