// Compare in the editor (issue 16 item 5): on the demo block, View > Faces Show > Split (Ctrl+4) and
// Difference (Ctrl+5) by their shortcuts, the toolbar slider moving the photo | model line, back to
// Photos (Ctrl+1); saves the pictures of both displays (docs/images/compare_faces.png is the first).
#include <QSlider>
#include <QSplitter>
#include <QtTest>

#include "annotation_layer.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "main_window.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 60000;

using testing::artifact;
}  // namespace

class TestCompareFaces : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void actionsHaveShortcutsAndTips();
  void shortcutsSwitchTheDisplay();
  void sliderMovesTheSplitLine();
  void lineIsDraggedWhateverTheTracingTool();
  void differenceComesWithoutBlocking();
  void savesPictures();
  void cleanupTestCase() { window_.reset(); }

 private:
  FacesView* view() const { return window_->facesView(); }
  void press(int digit) {
    QTest::keyClick(window_.get(), static_cast<Qt::Key>(Qt::Key_0 + digit), Qt::ControlModifier);
  }

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestCompareFaces::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  window_ = testing::openDemoWindow(dir_.filePath("demo"), 256, QSize(1400, 900), kTimeoutMs);
  QVERIFY(window_);
  // Shortcuts need an active window (xvfb has no window manager).
  window_->activateWindow();
  QApplication::setActiveWindow(window_.get());
  QTRY_VERIFY_WITH_TIMEOUT(window_->isActiveWindow(), kTimeoutMs);
  QCOMPARE(view()->display(), FaceDisplay::Photos);  // the demo has photos: they come first
}

void TestCompareFaces::actionsHaveShortcutsAndTips() {
  const QList<QAction*> actions = window_->faceDisplayActions();
  QCOMPARE(actions.size(), kFaceDisplayCount);
  QCOMPARE(actions[3]->text(), QStringLiteral("Split"));
  QCOMPARE(actions[3]->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_4));
  QCOMPARE(actions[4]->text(), QStringLiteral("Difference"));
  QCOMPARE(actions[4]->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_5));
  QVERIFY(actions[3]->toolTip().contains("photo") && actions[3]->toolTip().contains("model"));
  QVERIFY(actions[4]->toolTip().contains("lighter") && actions[4]->toolTip().contains("darker"));
  for (QAction* action : actions) QVERIFY(action->isEnabled());
}

void TestCompareFaces::shortcutsSwitchTheDisplay() {
  press(4);
  QCOMPARE(view()->display(), FaceDisplay::Split);
  QVERIFY(window_->faceDisplayActions()[3]->isChecked());
  press(5);
  QCOMPARE(view()->display(), FaceDisplay::Difference);
  QVERIFY(window_->faceDisplayActions()[4]->isChecked());
  QVERIFY(!window_->faceSlider()->isEnabled());  // nothing to set in Difference
  press(1);
  QCOMPARE(view()->display(), FaceDisplay::Photos);
  window_->faceDisplayActions()[3]->trigger();  // the toolbar button / menu entry
  QCOMPARE(view()->display(), FaceDisplay::Split);
}

void TestCompareFaces::sliderMovesTheSplitLine() {
  press(4);
  QSlider* slider = window_->faceSlider();
  QVERIFY(slider->isEnabled());
  slider->setValue(30);
  QCOMPARE(view()->splitPosition(), 0.3);
  view()->setSplitPosition(0.65);  // a drag on the faces moves the slider
  QCOMPARE(slider->value(), 65);
  // Blend keeps its own value: the slider shows the opacity there.
  press(3);
  QCOMPARE(slider->value(), static_cast<int>(std::lround(view()->blendOpacity() * 100)));
  slider->setValue(20);
  QCOMPARE(view()->splitPosition(), 0.65);
  QCOMPARE(view()->blendOpacity(), 0.2);
}

void TestCompareFaces::lineIsDraggedWhateverTheTracingTool() {
  // The tracing tools filter the view's mouse events; on the line they leave the press to it.
  press(4);
  view()->setSplitPosition(0.5);
  QCOMPARE(window_->annotationLayer()->tool(), AnnotationLayer::Tool::Select);
  const QRectF a = view()->faceRect(FaceId::A);
  const auto point = [&](double u) {
    return QPointF(a.left() + u * a.width(), a.top() + 0.3 * a.height()).toPoint();
  };
  QTest::mousePress(view(), Qt::LeftButton, {}, point(0.5));
  QVERIFY(view()->draggingSplit());
  QTest::mouseMove(view(), point(0.2));
  QTest::mouseRelease(view(), Qt::LeftButton, {}, point(0.2));
  QVERIFY(!view()->draggingSplit());
  QVERIFY(std::abs(view()->splitPosition() - 0.2) <= 1.5 / a.width());
  QCOMPARE(window_->faceSlider()->value(), static_cast<int>(std::lround(view()->splitPosition() * 100)));
  QVERIFY(window_->document()->annotations().traces.empty());
}

void TestCompareFaces::differenceComesWithoutBlocking() {
  press(5);
  QTRY_VERIFY_WITH_TIMEOUT(view()->differenceUpToDate(), kTimeoutMs);
  for (FaceId face : kAllFaces) {
    const QImage& map = view()->differenceMaps()[faceIndex(face)];
    QVERIFY(!map.isNull());
    QCOMPARE(map.size(), window_->document()->photos()[faceIndex(face)].size());  // the photo's pixel grid
  }
}

void TestCompareFaces::savesPictures() {
  // The faces get most of a large window, so the pictures show the tags and the legend.
  window_->resize(1600, 1000);
  auto* splitter = qobject_cast<QSplitter*>(window_->centralWidget());
  QVERIFY(splitter);
  splitter->setSizes({1000, 300});
  QTRY_VERIFY_WITH_TIMEOUT(view()->width() > 800, kTimeoutMs);
  press(4);
  view()->setSplitPosition(0.5);
  QVERIFY(view()->parentWidget()->grab().save(artifact("compare_faces")));
  press(5);
  QTRY_VERIFY_WITH_TIMEOUT(view()->differenceUpToDate(), kTimeoutMs);
  QVERIFY(view()->parentWidget()->grab().save(artifact("compare_difference")));
}

QTEST_MAIN(TestCompareFaces)
#include "test_compare_faces.moc"
