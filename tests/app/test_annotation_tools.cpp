// The ring-tracing tools of the faces view, end to end in the editor: real mouse and key events draw a
// polyline trace, select it, split it, join the pieces, number and renumber it, draw freehand, mark a
// knot on two faces, delete; each edit is one undo step that undo and redo walk through; detected rings
// become editable traces (one step, drawn traces kept); the project saves and reopens with them.
#include <QAction>
#include <QDir>
#include <QInputDialog>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <algorithm>
#include <glm/geometric.hpp>

#include "annotation_layer.hpp"
#include "demo/demo_block.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "gpu/surface_format.hpp"
#include "main_window.hpp"
#include "window_grab.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 60000;

using testing::artifact;
}  // namespace

class TestAnnotationTools : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void drawsAPolylineTrace();
  void selectsAndSplits();
  void joinsThePieces();
  void numbersAndRenumbers();
  void drawsFreehandSmoothly();
  void marksAKnotOnTwoFaces();
  void rubberBandSelectsAndDeleteRemoves();
  void dragsReleasesAndWeighsKnotMarks();
  void detectedRingsBecomeTracesInOneStep();
  void savesAndReopensTheAnnotations();
  void savesScreenshots();
  void cleanupTestCase() { window_.reset(); }

 private:
  // A widget point at fractions (fx, fy) of face `face` as drawn now.
  QPoint at(FaceId face, double fx, double fy) const {
    const QRectF r = view()->faceRect(face);
    return QPointF(r.left() + fx * r.width(), r.top() + fy * r.height()).toPoint();
  }
  FacesView* view() const { return window_->facesView(); }
  AnnotationLayer* layer() const { return window_->annotationLayer(); }
  const Annotations& annotations() const { return window_->document()->annotations(); }
  QUndoStack* undo() const { return window_->document()->undoStack(); }
  // Undo then redo the last step: the annotations go back to `before` and forward to what they are.
  void checkUndoRedo(const Annotations& before) {
    const Annotations after = annotations();
    undo()->undo();
    QCOMPARE(annotations(), before);
    undo()->redo();
    QCOMPARE(annotations(), after);
  }
  void key(int k, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QTest::keyClick(view(), static_cast<Qt::Key>(k), modifiers);
  }
  // Accepts the year dialog the layer opened with `value`.
  void answerDialog(const char* name, int value) {
    QInputDialog* dialog = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT((dialog = view()->findChild<QInputDialog*>(name)) != nullptr, kTimeoutMs);
    dialog->setIntValue(value);
    dialog->accept();
    QTRY_VERIFY_WITH_TIMEOUT(view()->findChild<QInputDialog*>(name) == nullptr, kTimeoutMs);
  }

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestAnnotationTools::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  DemoOptions options;
  options.facePixels = 128;
  options.samples = 1;
  const QString project =
      QString::fromStdString(writeDemo(dir_.filePath("demo").toStdString(), options).project.string());
  window_ = std::make_unique<MainWindow>(RenderSettings{3.2f, 1});
  window_->setAskBeforeDiscarding(false);
  window_->resize(1400, 900);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  // Shortcuts need an active window with the focus in the faces view (xvfb has no window manager).
  window_->activateWindow();
  QApplication::setActiveWindow(window_.get());
  QTRY_VERIFY_WITH_TIMEOUT(window_->isActiveWindow(), kTimeoutMs);
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(project);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(annotations().empty());
  view()->setFocus();
  QTRY_VERIFY_WITH_TIMEOUT(view()->hasFocus(), kTimeoutMs);
}

void TestAnnotationTools::drawsAPolylineTrace() {
  key(Qt::Key_P);
  QCOMPARE(layer()->tool(), AnnotationLayer::Tool::Polyline);
  const int steps = undo()->count();
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::A, 0.1, 0.3));
  QTest::mouseMove(view(), at(FaceId::A, 0.3, 0.4));
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::A, 0.5, 0.4));
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::A, 0.9, 0.3));
  QVERIFY(annotations().traces.empty());  // not finished yet
  key(Qt::Key_Return);
  QCOMPARE(undo()->count(), steps + 1);
  QCOMPARE(undo()->undoText(), QStringLiteral("Draw ring trace"));
  QCOMPARE(annotations().traces.size(), 1u);
  const RingTrace& trace = annotations().traces[0];
  QCOMPARE(trace.face, FaceId::A);
  QCOMPARE(trace.origin, TraceOrigin::Drawn);
  QCOMPARE(trace.points.size(), 3u);
  // The clicks land where they were made on the 40 mm face (within a screen pixel).
  const double mmPerPx = 40.0 / view()->faceRect(FaceId::A).width();
  QVERIFY(glm::length(trace.points[0] - glm::vec2(4.0f, 12.0f)) < 1.5 * mmPerPx);
  QVERIFY(glm::length(trace.points[2] - glm::vec2(36.0f, 12.0f)) < 1.5 * mmPerPx);
  QCOMPARE(layer()->selectedTraces(), std::vector<std::size_t>{0});
  checkUndoRedo(Annotations{});

  // Esc cancels a trace under way; a single point is not a trace.
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::B, 0.2, 0.2));
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::B, 0.6, 0.2));
  key(Qt::Key_Escape);
  key(Qt::Key_Return);
  QCOMPARE(annotations().traces.size(), 1u);
  QCOMPARE(undo()->count(), steps + 1);
}

void TestAnnotationTools::selectsAndSplits() {
  key(Qt::Key_V);
  QCOMPARE(layer()->tool(), AnnotationLayer::Tool::Select);
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::A, 0.5, 0.8));  // nothing there
  QVERIFY(layer()->selectedTraces().empty());
  QTest::mouseMove(view(), at(FaceId::A, 0.3, 0.35));
  QCOMPARE(layer()->hoveredTrace(), std::optional<std::size_t>(0));
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::A, 0.3, 0.35));  // on the first segment
  QCOMPARE(layer()->selectedTraces(), std::vector<std::size_t>{0});

  const Annotations before = annotations();
  QTest::mouseMove(view(), at(FaceId::A, 0.3, 0.35));
  key(Qt::Key_S);
  QCOMPARE(annotations().traces.size(), 2u);
  QCOMPARE(undo()->undoText(), QStringLiteral("Split ring trace"));
  const RingTrace& first = annotations().traces[0];
  const RingTrace& second = annotations().traces[1];
  QCOMPARE(first.points.back(), second.points.front());
  QVERIFY(std::abs(first.points.back().x - 12.0f) < 0.5f);  // at 0.3 of the 40 mm face
  QCOMPARE(first.points.front(), before.traces[0].points.front());
  QCOMPARE(second.points.back(), before.traces[0].points.back());
  QCOMPARE(layer()->selectedTraces(), (std::vector<std::size_t>{0, 1}));
  checkUndoRedo(before);
}

void TestAnnotationTools::joinsThePieces() {
  key(Qt::Key_V);
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::A, 0.2, 0.325));
  QCOMPARE(layer()->selectedTraces(), std::vector<std::size_t>{0});
  QTest::mouseClick(view(), Qt::LeftButton, Qt::ShiftModifier, at(FaceId::A, 0.7, 0.35));
  QCOMPARE(layer()->selectedTraces(), (std::vector<std::size_t>{0, 1}));
  const Annotations before = annotations();
  key(Qt::Key_J);
  QCOMPARE(annotations().traces.size(), 1u);
  QCOMPARE(undo()->undoText(), QStringLiteral("Join 2 ring traces"));
  QCOMPARE(annotations().traces[0].points.size(), 4u);  // the three clicks and the split point
  QCOMPARE(annotations().traces[0].points.front(), before.traces[0].points.front());
  QCOMPARE(annotations().traces[0].points.back(), before.traces[1].points.back());
  QCOMPARE(layer()->selectedTraces(), std::vector<std::size_t>{0});
  checkUndoRedo(before);
}

void TestAnnotationTools::numbersAndRenumbers() {
  QCOMPARE(layer()->selectedTraces(), std::vector<std::size_t>{0});
  Annotations before = annotations();
  key(Qt::Key_N);
  answerDialog("annotationYearDialog", 5);
  QCOMPARE(annotations().traces[0].year, std::optional<int>(5));
  QCOMPARE(undo()->undoText(), QStringLiteral("Number 1 trace(s) as year 5"));
  checkUndoRedo(before);

  before = annotations();
  key(Qt::Key_N, Qt::ShiftModifier);
  answerDialog("annotationYearOffsetDialog", 2);
  QCOMPARE(annotations().traces[0].year, std::optional<int>(7));
  checkUndoRedo(before);
}

void TestAnnotationTools::drawsFreehandSmoothly() {
  key(Qt::Key_D);
  QCOMPARE(layer()->tool(), AnnotationLayer::Tool::Freehand);
  const Annotations before = annotations();
  view()->setZoom(3.0, at(FaceId::A, 0.5, 0.7));  // a hand draws at a comfortable zoom
  const QRectF face = view()->faceRect(FaceId::A);
  const double mmPerPx = 40.0 / face.height();
  // A stroke along a pixel row across face A that wobbles 2 px up and down at every mouse event, one
  // event every 3 screen px (a mouse reports about that often at a hand's speed), whatever the zoom.
  const int row = at(FaceId::A, 0.5, 0.7).y();
  const double lineY = (row - face.top()) / face.height() * 40.0;
  const int x0 = at(FaceId::A, 0.1, 0.7).x(), x1 = at(FaceId::A, 0.9, 0.7).x();
  QTest::mousePress(view(), Qt::LeftButton, {}, QPoint(x0, row));
  int i = 1;
  for (int x = x0 + 3; x < x1; x += 3, ++i) QTest::mouseMove(view(), QPoint(x, row + (i % 2 ? 2 : -2)));
  QTest::mouseRelease(view(), Qt::LeftButton, {}, QPoint(x1, row + (i % 2 ? 2 : -2)));
  view()->fitToView();
  QCOMPARE(annotations().traces.size(), 2u);
  const RingTrace& stroke = annotations().traces[1];
  QCOMPARE(stroke.face, FaceId::A);
  QVERIFY(std::abs(stroke.points.front().x - 4.0f) < 2 * mmPerPx);
  QVERIFY(std::abs(stroke.points.back().x - 36.0f) < 2 * mmPerPx);
  // Smoothed: away from the ends (held where the stroke began and ended, wobble included) the trace
  // lies within a quarter of a screen pixel of the row, plus the 0.02 mm the layer's simplification
  // allows; the wobble was 2 px. The layer smooths with a Gaussian of sigma = max(0.4 mm, 4 screen px),
  // so the ends reach about 3 sigma into the stroke: the zone depends on the zoom (and so on the
  // window's layout), not on a fixed number of mm. The trace is checked every 0.25 mm along x, between
  // its vertices too (a straight stretch keeps few vertices).
  const double sigma = std::max(0.4, 4.0 * mmPerPx), endZone = 3.5 * sigma;
  QVERIFY(4.0 + endZone < 36.0 - endZone - 10.0);
  for (glm::vec2 p : stroke.points) {
    QVERIFY2(std::abs(p.y - lineY) < 2.5 * mmPerPx,
             qPrintable(QString("(%1, %2) vs row at %3 mm").arg(p.x).arg(p.y).arg(lineY)));
  }
  for (double x = 4.0 + endZone; x <= 36.0 - endZone; x += 0.25) {
    const auto next =
        std::find_if(stroke.points.begin(), stroke.points.end(), [&](glm::vec2 p) { return p.x >= x; });
    QVERIFY(next != stroke.points.begin() && next != stroke.points.end());
    const glm::vec2 a = *(next - 1), b = *next;
    const double y = a.y + (b.y - a.y) * (x - a.x) / std::max(1e-6, double(b.x - a.x));
    QVERIFY2(
        std::abs(y - lineY) < 0.25 * mmPerPx + 0.02,
        qPrintable(QString("at x = %1 mm the trace is at %2, the row at %3 mm").arg(x).arg(y).arg(lineY)));
  }
  checkUndoRedo(before);
}

void TestAnnotationTools::marksAKnotOnTwoFaces() {
  key(Qt::Key_K);
  const Annotations before = annotations();
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::C, 0.3, 0.75));
  QCOMPARE(annotations().knots.size(), 1u);
  const Annotations oneMark = annotations();
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::F, 0.6, 0.2));
  QCOMPARE(annotations().knots.size(), 2u);
  QCOMPARE(annotations().knots[0].knot, annotations().knots[1].knot);
  QCOMPARE(annotations().knots[0].face, FaceId::C);
  QCOMPARE(annotations().knots[1].face, FaceId::F);
  QVERIFY(glm::length(annotations().knots[0].point - glm::vec2(12.0f, 30.0f)) < 0.5f);
  checkUndoRedo(oneMark);
  undo()->undo();
  undo()->undo();
  QCOMPARE(annotations(), before);
  undo()->redo();
  undo()->redo();
  QCOMPARE(annotations().knots.size(), 2u);
}

void TestAnnotationTools::rubberBandSelectsAndDeleteRemoves() {
  key(Qt::Key_V);
  // A box over the lower part of face A catches the freehand trace only.
  QTest::mousePress(view(), Qt::LeftButton, {}, at(FaceId::A, 0.02, 0.6));
  QTest::mouseMove(view(), at(FaceId::A, 0.5, 0.75));
  QTest::mouseMove(view(), at(FaceId::A, 0.98, 0.8));
  QTest::mouseRelease(view(), Qt::LeftButton, {}, at(FaceId::A, 0.98, 0.8));
  QCOMPARE(layer()->selectedTraces(), std::vector<std::size_t>{1});
  const Annotations before = annotations();
  key(Qt::Key_Delete);
  QCOMPARE(annotations().traces.size(), 1u);
  QCOMPARE(annotations().traces[0], before.traces[0]);
  QCOMPARE(annotations().knots, before.knots);
  checkUndoRedo(before);

  // A knot is picked whole (both marks) and deleted with Delete.
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::C, 0.3, 0.75));
  QCOMPARE(layer()->selectedKnots().size(), 2u);
  const Annotations withKnot = annotations();
  key(Qt::Key_Delete);
  QVERIFY(annotations().knots.empty());
  checkUndoRedo(withKnot);
  undo()->undo();  // keep the knot for the file round trip
  QCOMPARE(annotations().knots.size(), 2u);
}

// Issue 19 item 1: a knot mark is dragged to where the knot really comes out, released (R) so that the
// rings place the knot, given an accuracy (M), its edge on the photo ignored (E); each is one undo step,
// drawn as it is.
void TestAnnotationTools::dragsReleasesAndWeighsKnotMarks() {
  key(Qt::Key_V);
  const Annotations before = annotations();
  QCOMPARE(before.knots.size(), 2u);
  QCOMPARE(before.knots[0].face, FaceId::C);
  QVERIFY(!before.knots[0].released);
  QCOMPARE(before.knots[0].accuracyMm, kDefaultKnotMarkAccuracyMm);

  QTest::mousePress(view(), Qt::LeftButton, {}, at(FaceId::C, 0.3, 0.75));
  QTest::mouseMove(view(), at(FaceId::C, 0.4, 0.6));
  QTest::mouseMove(view(), at(FaceId::C, 0.5, 0.5));
  QTest::mouseRelease(view(), Qt::LeftButton, {}, at(FaceId::C, 0.5, 0.5));
  QCOMPARE(annotations().knots.size(), 2u);
  const glm::vec2 faceMm = faceSizeMm(window_->document()->project().block, FaceId::C);
  QVERIFY(glm::length(annotations().knots[0].point - 0.5f * faceMm) < 0.5f);
  QCOMPARE(annotations().knots[1], before.knots[1]);  // the other mark stays
  checkUndoRedo(before);
  QCOMPARE(layer()->selectedKnots().size(), 2u);  // the dragged knot stays selected

  // A click without moving only selects; Esc during a drag puts the mark back.
  const Annotations moved = annotations();
  QTest::mousePress(view(), Qt::LeftButton, {}, at(FaceId::C, 0.5, 0.5));
  QTest::mouseMove(view(), at(FaceId::C, 0.7, 0.3));
  key(Qt::Key_Escape);
  QTest::mouseRelease(view(), Qt::LeftButton, {}, at(FaceId::C, 0.7, 0.3));
  QCOMPARE(annotations(), moved);
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::C, 0.5, 0.5));
  QCOMPARE(annotations(), moved);
  QCOMPARE(layer()->selectedKnots().size(), 2u);

  key(Qt::Key_R);
  QVERIFY(annotations().knots[0].released && annotations().knots[1].released);
  checkUndoRedo(moved);
  const Annotations released = annotations();
  key(Qt::Key_R);  // all released: R holds them again
  QVERIFY(!annotations().knots[0].released && !annotations().knots[1].released);
  checkUndoRedo(released);

  // A wrong edge on the photo (a resin streak beside the knot): E ignores it, E again uses it.
  const Annotations held = annotations();
  key(Qt::Key_E);
  QVERIFY(annotations().knots[0].ignoreEdge && annotations().knots[1].ignoreEdge);
  QVERIFY(undo()->undoText().contains(QStringLiteral("Ignore Knot Edges")));
  checkUndoRedo(held);
  const Annotations ignored = annotations();
  key(Qt::Key_E);
  QVERIFY(!annotations().knots[0].ignoreEdge && !annotations().knots[1].ignoreEdge);
  checkUndoRedo(ignored);

  key(Qt::Key_M);
  QInputDialog* dialog = nullptr;
  QTRY_VERIFY_WITH_TIMEOUT((dialog = view()->findChild<QInputDialog*>("knotAccuracyDialog")) != nullptr,
                           kTimeoutMs);
  QCOMPARE(dialog->doubleValue(), double(kDefaultKnotMarkAccuracyMm));
  dialog->setDoubleValue(2.5);
  dialog->accept();
  QTRY_VERIFY_WITH_TIMEOUT(view()->findChild<QInputDialog*>("knotAccuracyDialog") == nullptr, kTimeoutMs);
  QCOMPARE(annotations().knots[0].accuracyMm, 2.5f);
  QCOMPARE(annotations().knots[1].accuracyMm, 2.5f);
  QVERIFY(QDir().mkpath(KERF_TEST_ARTIFACTS_DIR));
  view()->setZoom(3.0, at(FaceId::C, 0.5, 0.5));
  QTest::qWait(50);
  QVERIFY(view()->grab().toImage().save(artifact("annotation_knot_accuracy")));  // the circles, to look at
  view()->fitToView();

  // Back to the marks as they were, for the tests that follow.
  for (int steps = 0; steps < 8 && annotations() != before; ++steps) undo()->undo();
  QCOMPARE(annotations(), before);
}

void TestAnnotationTools::detectedRingsBecomeTracesInOneStep() {
  const Annotations drawn = annotations();
  const int steps = undo()->index();
  QSignalSpy detected(window_.get(), &MainWindow::ringsDetected);
  QSignalSpy failed(window_.get(), &MainWindow::ringJobFailed);
  window_->detectRingsAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() + failed.count() > 0, kTimeoutMs);
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  QCOMPARE(undo()->index(), steps + 1);
  QVERIFY(undo()->undoText().startsWith(QStringLiteral("Detect rings")));
  int detectedCount = 0;
  for (const RingTrace& t : annotations().traces) detectedCount += t.origin == TraceOrigin::Detected;
  QVERIFY2(detectedCount >= 6, qPrintable(QString::number(detectedCount)));
  QCOMPARE(annotations().traces[0], drawn.traces[0]);  // the hand-drawn trace stays
  QCOMPARE(annotations().knots, drawn.knots);

  // Again: the detected traces are replaced, not added twice.
  window_->detectRingsAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() + failed.count() > 1, kTimeoutMs);
  int again = 0;
  for (const RingTrace& t : annotations().traces) again += t.origin == TraceOrigin::Detected;
  QCOMPARE(again, detectedCount);
  QCOMPARE(static_cast<int>(annotations().traces.size()), detectedCount + 1);

  // Undo takes the detection back in one step (the second detection changed nothing, so no step).
  undo()->setIndex(steps);
  QCOMPARE(annotations(), drawn);
  undo()->redo();
  QCOMPARE(static_cast<int>(annotations().traces.size()), detectedCount + 1);

  // With Rings > Learned Ring Detector checked, the network finds them: again one step, the drawn trace kept.
  auto* learned = window_->findChild<QAction*>("learnedDetectorAction");
  QVERIFY(learned && learned->isCheckable() && !learned->isChecked());  // the classical one by default
  learned->setChecked(true);
  QCOMPARE(window_->rings()->detector(), std::string("learned"));
  const int before = undo()->index();
  window_->detectRingsAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() + failed.count() > 2, kTimeoutMs);
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  QCOMPARE(window_->rings()->ringDetection()->detector, std::string("learned"));
  int byNetwork = 0;
  for (const RingTrace& t : annotations().traces) byNetwork += t.origin == TraceOrigin::Detected;
  QVERIFY2(byNetwork >= 6, qPrintable(QString::number(byNetwork)));
  QCOMPARE(annotations().traces[0], drawn.traces[0]);
  undo()->setIndex(before);  // the classical detection back, for the tests that follow
  learned->setChecked(false);
  QCOMPARE(window_->rings()->detector(), std::string("classical"));
}

void TestAnnotationTools::savesAndReopensTheAnnotations() {
  const Annotations saved = annotations();
  QVERIFY(!saved.traces.empty());
  // The autosave copy holds them too.
  QVERIFY(window_->document()->snapshot(dir_.path()).contains("\"annotations\""));
  const QString path = dir_.filePath("saved/annotated.kerf");
  QVERIFY(QDir().mkpath(dir_.filePath("saved")));
  QVERIFY(window_->saveAs(path));
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(
      QString::fromStdString(window_->document()->project().facePhotos[0].parent_path().string()));
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(annotations().empty());  // the sample folder has none
  window_->openDocument(path);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 2, kTimeoutMs);
  QCOMPARE(annotations().traces.size(), saved.traces.size());
  for (std::size_t i = 0; i < saved.traces.size(); ++i) {
    QCOMPARE(annotations().traces[i].year, saved.traces[i].year);
    QCOMPARE(annotations().traces[i].origin, saved.traces[i].origin);
    QCOMPARE(annotations().traces[i].points.size(), saved.traces[i].points.size());
    for (std::size_t k = 0; k < saved.traces[i].points.size(); ++k)
      QVERIFY(glm::length(annotations().traces[i].points[k] - saved.traces[i].points[k]) < 1e-4f);
  }
  QCOMPARE(annotations().knots.size(), saved.knots.size());
  QCOMPARE(layer()->annotations(), annotations());

  // And the export in the Mokume format: the numbered trace and the knot.
  const QString folder = dir_.filePath("mokume");
  QVERIFY(window_->rings()->exportAnnotations(folder));
  QVERIFY(QFileInfo::exists(folder + "/A_ann.png"));
  QVERIFY(QFileInfo::exists(folder + "/C_knot.png"));
  QVERIFY(QFileInfo::exists(folder + "/F_knot.png"));
}

void TestAnnotationTools::savesScreenshots() {
  QVERIFY(QDir().mkpath(KERF_TEST_ARTIFACTS_DIR));
  // A few more numbered traces on face B, and the selection and hover shown.
  key(Qt::Key_P);
  for (int k = 0; k < 3; ++k) {
    QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::B, 0.1, 0.2 + 0.25 * k));
    QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::B, 0.5, 0.3 + 0.25 * k));
    QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::B, 0.9, 0.25 + 0.25 * k));
    key(Qt::Key_Return);
    key(Qt::Key_N);
    answerDialog("annotationYearDialog", 3 + k);
  }
  key(Qt::Key_V);
  QTest::mouseClick(view(), Qt::LeftButton, {}, at(FaceId::A, 0.2, 0.325));
  QTest::qWait(50);
  QVERIFY(view()->grab().toImage().save(artifact("annotation_faces")));
  QVERIFY(grabWindowWithGl(window_.get()).save(artifact("annotation_window")));
  view()->setZoom(3.0, at(FaceId::A, 0.5, 0.4));
  QTest::qWait(50);
  QVERIFY(view()->grab().toImage().save(artifact("annotation_faces_zoomed")));
  view()->fitToView();

  // The same annotations in a faces view of a comfortable size, to judge how they sit on the wood.
  FacesView large;
  large.resize(1400, 1000);
  large.setBlock(window_->document()->project().block);
  large.setPhotos(window_->document()->photos());
  auto* largeLayer = new AnnotationLayer(&large);  // owned by the view
  largeLayer->setAnnotations(annotations());
  largeLayer->setSelection({0});
  QVERIFY(large.grab().toImage().save(artifact("annotation_faces_large")));
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  // The default window layout, whatever an earlier run saved: pixel positions in the tests depend on it.
  qputenv("KERF_DEFAULT_LAYOUT", "1");
  TestAnnotationTools test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_annotation_tools.moc"
