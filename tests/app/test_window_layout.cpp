// The editor's default layout (issue 20 item 1): at 1600 x 1000 and at 1366 x 768 the faces, the 3D block
// and the true-scale cut (shown, with a cut) are all visible and take most of the window; the log and the
// history are hidden until wanted; a layout the user made is remembered (per user, QSettings), one saved by
// another layout version is not, and View > Reset Layout brings the default back. With a knotted block,
// the Knots tab raised keeps the wood's share at 1366 x 768.
#include <QDockWidget>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include "block_knot_table.hpp"
#include "cut_view.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "gpu/surface_format.hpp"
#include "main_window.hpp"
#include "viewport3d.hpp"
#include "window_grab.hpp"
#include "window_layout.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 60000;

// The share of the window's area covered by the visible part of `widgets`.
double shareOfWindow(const QWidget* window, const QList<const QWidget*>& widgets) {
  const QRect frame = window->rect();
  double covered = 0;
  for (const QWidget* widget : widgets) {
    if (!widget->isVisible()) continue;
    const QRect r(widget->mapTo(window, QPoint(0, 0)), widget->size());
    const QRect visible = r.intersected(frame);
    covered += double(visible.width()) * visible.height();
  }
  return covered / (double(frame.width()) * frame.height());
}

QDockWidget* dock(const MainWindow& window, const char* name) {
  return window.findChild<QDockWidget*>(name);
}

}  // namespace

class TestWindowLayout : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void woodFillsTheWindow_data();
  void woodFillsTheWindow();
  void knotTableKeepsTheWoodsShare();
  void rememberedPerUser();
  void otherLayoutVersionIsIgnored();
  void resetLayoutBringsTheDefaultBack();

 private:
  std::unique_ptr<MainWindow> open(QSize size) {
    return testing::openDemoWindow(dir_.filePath("demo"), 64, size, kTimeoutMs);
  }

  QTemporaryDir dir_;
};

void TestWindowLayout::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  // This test's own settings, never the user's nor another test's.
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.filePath("settings"));
  QSettings().clear();
}

void TestWindowLayout::woodFillsTheWindow_data() {
  QTest::addColumn<QSize>("size");
  QTest::newRow("1600x1000") << QSize(1600, 1000);
  QTest::newRow("1366x768") << QSize(1366, 768);
}

void TestWindowLayout::woodFillsTheWindow() {
  QFETCH(QSize, size);
  QSettings().clear();  // the default layout
  auto window = open(size);
  QVERIFY(window);
  QCOMPARE(window->size(), size);  // nothing in the window needs more room than that
  // The cut panel is shown, with a cut, next to the faces and the block.
  QVERIFY(dock(*window, "cutDock")->isVisible());
  QVERIFY(window->cutView()->isVisible());
  QVERIFY(window->document()->cutEnabled());
  QVERIFY(dock(*window, "parametersDock")->isVisible());
  for (const QString& name : WindowLayout::smallDockNames())
    QVERIFY2(!dock(*window, qPrintable(name))->isVisible(), qPrintable(name + " is shown by default"));
  window->viewport()->refineNow();
  QVERIFY(grabWindowWithGl(window.get())
              .save(testing::artifact(QStringLiteral("layout_%1x%2").arg(size.width()).arg(size.height()))));
  // Each of the three wood views is large: at least 12 % of the window.
  const QList<const QWidget*> wood = {window->facesView(), window->viewport(), window->cutView()};
  for (const QWidget* view : wood) {
    const double share = shareOfWindow(window.get(), {view});
    QVERIFY2(share > 0.12, qPrintable(QStringLiteral("%1 covers %2 of the window")
                                          .arg(view->metaObject()->className())
                                          .arg(share, 0, 'f', 3)));
  }
  const double share = shareOfWindow(window.get(), wood);
  qInfo("%dx%d: faces + block + cut cover %.1f %% of the window", size.width(), size.height(), 100 * share);
  QVERIFY2(share > 0.5, qPrintable(QStringLiteral("the wood covers only %1 of the window").arg(share)));
  QSettings().clear();
}

// A block with a knot at 1366 x 768: the Knots dock is a tab beside the parameters; raised, the table fits
// its width and the wood keeps more than half of the window.
void TestWindowLayout::knotTableKeepsTheWoodsShare() {
  QSettings().clear();
  auto window = testing::openDemoWindow(dir_.filePath("knotty"), 64, {1366, 768}, kTimeoutMs, true);
  QVERIFY(window);
  QDockWidget* knots = dock(*window, "blockKnotsDock");
  QVERIFY(knots->isVisible() || window->tabifiedDockWidgets(dock(*window, "parametersDock")).contains(knots));
  knots->raise();
  QTest::qWait(50);
  QVERIFY(knots->isVisible());
  QCOMPARE(window->size(), QSize(1366, 768));
  QCOMPARE(window->blockKnotTable()->table()->rowCount(), 1);
  QVERIFY2(!window->blockKnotTable()->table()->horizontalScrollBar()->isVisible(),
           "the knot table's columns do not fit the dock");
  const QList<const QWidget*> wood = {window->facesView(), window->viewport(), window->cutView()};
  const double share = shareOfWindow(window.get(), wood);
  qInfo("1366x768 with the Knots tab: faces + block + cut cover %.1f %% of the window", 100 * share);
  QVERIFY2(share > 0.5, qPrintable(QStringLiteral("the wood covers only %1 of the window").arg(share)));
  QSettings().clear();
}

void TestWindowLayout::rememberedPerUser() {
  QSettings().clear();
  {
    auto window = open({1400, 900});
    QVERIFY(window);
    dock(*window, "historyDock")->show();
    dock(*window, "cutDock")->hide();
  }  // closing saves the layout
  auto window = open({1400, 900});
  QVERIFY(window);
  QVERIFY(dock(*window, "historyDock")->isVisible());
  QVERIFY(!dock(*window, "cutDock")->isVisible());
}

void TestWindowLayout::otherLayoutVersionIsIgnored() {
  // A layout saved by another version of the arrangement: the default instead.
  QSettings().setValue("window/layoutVersion", WindowLayout::kVersion - 1);
  auto window = open({1400, 900});
  QVERIFY(window);
  QVERIFY(dock(*window, "cutDock")->isVisible());
  QVERIFY(!dock(*window, "historyDock")->isVisible());
}

void TestWindowLayout::resetLayoutBringsTheDefaultBack() {
  QSettings().clear();
  auto window = open({1400, 900});
  QVERIFY(window);
  QDockWidget* cut = dock(*window, "cutDock");
  QDockWidget* log = dock(*window, "logDock");
  cut->setFloating(true);
  log->show();
  dock(*window, "parametersDock")->hide();
  window->windowLayout()->resetAction()->trigger();
  QTest::qWait(0);  // the docks are sized from the event loop
  QVERIFY(!cut->isFloating());
  QVERIFY(cut->isVisible());
  QCOMPARE(window->dockWidgetArea(cut), Qt::BottomDockWidgetArea);
  QVERIFY(!log->isVisible());
  QVERIFY(dock(*window, "parametersDock")->isVisible());
  QVERIFY(shareOfWindow(window.get(), {window->facesView(), window->viewport(), window->cutView()}) > 0.5);
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  TestWindowLayout test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_window_layout.moc"
