// Issue 19 item 1 in the editor: on a fitted block with a marked knot, dragging a knot mark refits the
// knot in the background (RingsController::refitKnots) and the new knot passes within the mark's
// accuracy of where the mark now is; it is one undo step of its own; releasing the marks refits too.
#include <QDir>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "annotation_layer.hpp"
#include "demo/demo_block.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "field/block_knots.hpp"
#include "field/growth_field.hpp"
#include "gpu/surface_format.hpp"
#include "main_window.hpp"
#include "rings/annotations.hpp"
#include "rings_controller.hpp"

using namespace kerf;

namespace {
// Only a hang guard: the waits are on the editor's signals. The whole test takes 35-44 s released and about
// 290 s under ASan + UBSan (2026-12-08, an idle 2-core machine: the former 240 s bound on the knot fit failed
// there), so the bound sits just under ctest's TIMEOUT for this test (tests/app/CMakeLists.txt), and no
// machine's speed decides the verdict.
constexpr int kTimeoutMs = 1700000;
}  // namespace

class TestKnotsFollowMarks : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void draggingAMarkRefitsTheKnotThroughIt();
  void releasingTheMarksRefitsToo();
  void cleanupTestCase() { window_.reset(); }

 private:
  void checkOutlinesFollowTheMarks();
  Document* document() const { return window_->document(); }
  // The fitted knot's axis: its distance from mark `i` in block mm.
  double axisToMark(std::size_t i) const {
    const Project& p = document()->project();
    const KnotMark& m = p.annotations.knots[i];
    for (const BlockKnot& k : p.knots)
      if (k.id == m.knot)
        return knotAxisDistance(&k.origin.x, &k.direction.x, faceMmToBlock(p.block, m.face, m.point));
    return -1;
  }

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestKnotsFollowMarks::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  DemoOptions options;  // as `kerf-cli demo --size 96 --samples 1 --no-photo-look --knot`
  options.facePixels = 96;
  options.samples = 1;
  options.photoLook = false;
  options.knot = true;
  const QString project =
      QString::fromStdString(writeDemo(dir_.filePath("knotty").toStdString(), options).project.string());
  window_ = std::make_unique<MainWindow>(RenderSettings{2.4f, 1});
  window_->setAskBeforeDiscarding(false);
  window_->resize(1400, 900);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(project);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QCOMPARE(document()->annotations().knots.size(), 2u);

  QSignalSpy detected(window_.get(), &MainWindow::ringsDetected);
  QSignalSpy fitted(window_.get(), &MainWindow::growthFieldFitted);
  QSignalSpy failed(window_.get(), &MainWindow::ringJobFailed);
  window_->detectRingsAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(detected.count() + failed.count() > 0, kTimeoutMs);
  window_->fitGrowthAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(fitted.count() + failed.count() > 0, kTimeoutMs);
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  QCOMPARE(document()->project().knots.size(), 1u);
  for (std::size_t i = 0; i < 2; ++i)
    QVERIFY2(axisToMark(i) <= 1.0, qPrintable(QString::number(axisToMark(i))));
  // Issue 19 item 2: the knot's edge is found where it enters (face F, round) and where it leaves (face B,
  // long and oblique), is drawn around its marks, and the fitted knot's cross-section on each face is
  // the outline's size.
  checkOutlinesFollowTheMarks();
}

void TestKnotsFollowMarks::checkOutlinesFollowTheMarks() {
  AnnotationLayer* layer = window_->annotationLayer();
  const Project& p = document()->project();
  QCOMPARE(layer->knotOutlines().size(), 2u);
  int found = 0;
  for (std::size_t i = 0; i < 2; ++i) {
    const KnotOutline* o = layer->outlineOfMark(i);
    std::printf("knot mark %zu on %c: %s\n", i, faceLetter(layer->knotOutlines()[i].face),
                layer->knotOutlines()[i].note.c_str());
    if (!o) {
      QVERIFY(!layer->knotOutlines()[i].note.empty());
      continue;
    }
    ++found;
    // The fitted knot's width on the face along the outline's two axes, from the field itself.
    const KnotMark& m = p.annotations.knots[i];
    const GrowthField stem(p.params, *p.rates);
    const KnotSettings settings = KnotSettings::fromParameters(p.params);
    const auto inKnot = [&](glm::vec3 q) {  // T_k < G (Mokume Eq. 7), with the knot's taper
      const float g = stem.evaluate(q);
      for (const BlockKnot& k : p.knots) {
        const float v = knotSpeedAt(k.speed, k.taper, k.taperAge, g, maxKnotSpeed(settings));
        if (knotAxisDistance(&k.origin.x, &k.direction.x, q) / (v * p.params.ringWidth) < g) return true;
      }
      return false;
    };
    for (int axis = 0; axis < 2; ++axis) {
      const float angle = o->angleRad + (axis == 0 ? 0.0f : 1.5707963f);
      const glm::vec2 dir(std::cos(angle), std::sin(angle));
      float width = 0;
      for (float sign : {-1.0f, 1.0f}) {
        float r = 0;
        while (r < 15.0f && inKnot(faceMmToBlock(p.block, m.face, o->center + sign * r * dir))) r += 0.05f;
        width += r;
      }
      const float seen = 2.0f * (axis == 0 ? o->semiAxesMm.x : o->semiAxesMm.y);
      std::printf("knot mark %zu on %c, axis %d: outline %.2f mm, fitted knot %.2f mm\n", i,
                  faceLetter(m.face), axis, seen, width);
      QVERIFY2(std::abs(width - seen) < 0.2f * seen + 0.5f,
               qPrintable(QString("%1 vs %2").arg(width).arg(seen)));
    }
  }
  QCOMPARE(found, 2);
  // To look at: the outlines around the marks, zoomed on each face.
  QVERIFY(QDir().mkpath(KERF_TEST_ARTIFACTS_DIR));
  FacesView* view = window_->facesView();
  for (std::size_t i = 0; i < 2; ++i) {
    const KnotMark& m = p.annotations.knots[i];
    view->fitToView();
    view->setZoom(4.0, layer->toWidget(m.face, m.point));
    QTest::qWait(50);
    QVERIFY(view->grab().toImage().save(
        QString(KERF_TEST_ARTIFACTS_DIR "/knot_outline_%1.png").arg(QChar(faceLetter(m.face)))));
  }
  view->fitToView();
}

void TestKnotsFollowMarks::draggingAMarkRefitsTheKnotThroughIt() {
  FacesView* view = window_->facesView();
  AnnotationLayer* layer = window_->annotationLayer();
  layer->setTool(AnnotationLayer::Tool::Select);
  const std::vector<BlockKnot> before = document()->project().knots;
  const KnotMark mark = document()->annotations().knots[0];
  // 3 mm along the face: a user correcting where the knot comes out.
  const glm::vec2 target = mark.point + glm::vec2(3.0f, 0.0f);
  QSignalSpy refitted(window_->rings(), &RingsController::knotsRefitted);
  // What the refit says in the log (its own time), printed for the docs.
  QObject scope;
  connect(window_->rings(), &EditorController::logged, &scope, [](const QString&, const QString& text) {
    if (text.contains("Knot")) std::printf("log: %s\n", qPrintable(text));
  });
  QElapsedTimer clock;
  QTest::mousePress(view, Qt::LeftButton, {}, layer->toWidget(mark.face, mark.point).toPoint());
  QTest::mouseMove(view, layer->toWidget(mark.face, mark.point + glm::vec2(1.5f, 0.0f)).toPoint());
  QTest::mouseMove(view, layer->toWidget(mark.face, target).toPoint());
  QTest::mouseRelease(view, Qt::LeftButton, {}, layer->toWidget(mark.face, target).toPoint());
  clock.start();
  const glm::vec2 moved = document()->annotations().knots[0].point;
  QVERIFY2(glm::length(moved - target) < 0.6f, qPrintable(QString("%1, %2").arg(moved.x).arg(moved.y)));
  QVERIFY(axisToMark(0) > 1.0);  // the old knot misses the moved mark
  const int steps = document()->undoStack()->count();

  QTRY_COMPARE_WITH_TIMEOUT(refitted.count(), 1, kTimeoutMs);
  std::printf(
      "the knot followed its mark %.2f s after the mouse was released (0.3 s of it the wait for "
      "the marks to be still)\n",
      clock.elapsed() / 1000.0);
  QVERIFY(document()->project().knots != before);
  // The outline is found again from the moved mark (3 mm off the knot's centre, still inside it).
  QVERIFY(window_->annotationLayer()->outlineOfMark(0) != nullptr);
  QCOMPARE(window_->annotationLayer()->outlineOfMark(0)->seed, moved);
  for (std::size_t i = 0; i < 2; ++i)
    QVERIFY2(axisToMark(i) <= 1.0, qPrintable(QString::number(axisToMark(i))));
  QCOMPARE(document()->undoStack()->count(), steps + 1);  // the refit is its own step
  QCOMPARE(document()->undoStack()->undoText(), QString("Knots Follow Their Marks"));
  document()->undoStack()->undo();
  QVERIFY(document()->project().knots == before);
  QCOMPARE(document()->annotations().knots[0].point, moved);  // the move itself stays
  document()->undoStack()->redo();
  QVERIFY(axisToMark(0) <= 1.0);
}

void TestKnotsFollowMarks::releasingTheMarksRefitsToo() {
  AnnotationLayer* layer = window_->annotationLayer();
  QSignalSpy refitted(window_->rings(), &RingsController::knotsRefitted);
  layer->setSelection({}, {0, 1});
  layer->toggleReleaseOfSelectedKnots();
  QVERIFY(document()->annotations().knots[0].released && document()->annotations().knots[1].released);
  QTRY_COMPARE_WITH_TIMEOUT(refitted.count(), 1, kTimeoutMs);
  QCOMPARE(document()->project().knots.size(), 1u);
  // Undo of the edit does not refit on its own (it would push a step and drop the redo).
  const int steps = document()->undoStack()->count();
  document()->undoStack()->undo();
  document()->undoStack()->undo();
  QTest::qWait(1000);
  QCOMPARE(refitted.count(), 1);
  QCOMPARE(document()->undoStack()->count(), steps);
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  qputenv("KERF_DEFAULT_LAYOUT", "1");
  TestKnotsFollowMarks test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_knots_follow_marks.moc"
