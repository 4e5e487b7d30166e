// The editor with a log: a random log opens as a document, the board moves (dragged in the log view and
// typed in the Board dock) and the faces follow, knots are added, edited and deleted as undo steps, and
// the project (log and board) and the log alone are saved and read back; the cut panel and the 3D view
// show the log's wood with knots (GLSL), the same field as the faces, and follow the board and the cut.
// Saves screenshots.
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include "board_controls.hpp"
#include "cut_view.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "gpu/surface_format.hpp"
#include "image_change.hpp"
#include "image_pane.hpp"
#include "io/log_data_import.hpp"
#include "knot_table.hpp"
#include "log_commands.hpp"
#include "log_view.hpp"
#include "main_window.hpp"
#include "panel_controls.hpp"
#include "render/board_wood.hpp"
#include "viewport3d.hpp"
#include "window_grab.hpp"

using namespace kerf;
using kerf::testing::changedShare;

namespace {
constexpr int kTimeoutMs = 60000;

QPoint rounded(QPointF p) {
  return p.toPoint();
}
}  // namespace

class TestLogView : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void opensRandomLogAsDocument();
  void draggingTheBoardChangesTheFaces();
  void typedPlacementIsOneUndoStep();
  void addsEditsAndDeletesKnots();
  void savesAndReopensProjectWithLog();
  void closesLogAsUndoStep();
  void cutAndThreeDShowTheLogsWood();
  void showsPanelsFromTheLog();
  void savesScreenshot();
  void cleanupTestCase() { window_.reset(); }

 private:
  Document* document() const { return window_->document(); }
  const ProjectLog& log() const { return *document()->log(); }
  // Waits for the full-resolution faces after an edit.
  bool waitForFaces(QSignalSpy& rendered, int count = 1) {
    return QTest::qWaitFor([&] { return rendered.count() >= count && !window_->isBusy(); }, kTimeoutMs);
  }

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestLogView::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  qputenv("KERF_DEFAULT_LAYOUT", "1");
  window_ = std::make_unique<MainWindow>(RenderSettings{2.0f, 1});
  window_->setAskBeforeDiscarding(false);
  window_->resize(1500, 950);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TestLogView::opensRandomLogAsDocument() {
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  QVERIFY(!window_->hasDocument());
  window_->logBoard()->openRandomLog(7);
  QVERIFY(window_->hasDocument());
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(document()->log().has_value());
  QVERIFY(log().log.knots.size() > 5);
  // The document's block is the board; the faces are the board's, at the window's px/mm.
  QCOMPARE(document()->project().block.size(), log().board.size);
  const FacesView* faces = window_->facesView();
  for (FaceId face : kAllFaces) {
    const QImage& image = faces->faces()[faceIndex(face)];
    QVERIFY(!image.isNull());
    const FaceFrame frame = Block(log().board.size).face(face);
    QCOMPARE(image.width(), static_cast<int>(std::lround(std::max(frame.widthMm, frame.heightMm) * 2.0f)) *
                                    (frame.widthMm >= frame.heightMm ? 1 : 0) +
                                image.width() * (frame.widthMm >= frame.heightMm ? 0 : 1));
  }
  QCOMPARE(window_->logView()->log()->knots.size(), log().log.knots.size());
  QCOMPARE(window_->knotTable()->table()->rowCount(), static_cast<int>(log().log.knots.size()));
  // The 3D view and the cut panel evaluate the board's wood (the knot model in GLSL), not photos.
  QVERIFY(window_->viewport()->boardWood());
  QVERIFY(!window_->viewport()->showPhotos());
  QCOMPARE(window_->cutView()->boardWood(), window_->viewport()->boardWood());
  QVERIFY(window_->viewport()->boardWood()->board == log().board);
  QCOMPARE(document()->undoStack()->count(), 0);
}

void TestLogView::draggingTheBoardChangesTheFaces() {
  const QImage before = window_->facesView()->faces()[0];
  const Board start = log().board;
  const int steps = document()->undoStack()->index();
  LogView* view = window_->logView();
  view->parentWidget()->show();
  // Drag the board along the log in the side view: press on the board's centre, move 40 px right.
  const QPoint from = rounded(view->sideViewPoint(start.center));
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  QTest::mousePress(view, Qt::LeftButton, {}, from);
  for (int i = 1; i <= 8; ++i) QTest::mouseMove(view, from + QPoint(5 * i, 0));
  QTest::mouseRelease(view, Qt::LeftButton, {}, from + QPoint(40, 0));
  QVERIFY(log().board.center.z > start.center.z + 10.0f);  // up the log
  QCOMPARE(log().board.center.x, start.center.x);
  QCOMPARE(document()->undoStack()->index(), steps + 1);  // the whole drag is one step
  QCOMPARE(document()->undoStack()->undoText(), QStringLiteral("Move board"));
  QVERIFY(waitForFaces(rendered));
  const double changed = changedShare(before, window_->facesView()->faces()[0]);
  qInfo("board moved %.1f mm up the log: %.1f %% of face A changed", log().board.center.z - start.center.z,
        100.0 * changed);
  QVERIFY(changed > 0.2);
  // The Board dock follows.
  QCOMPARE(window_->boardControls()->spinBox(2)->value(), std::round(log().board.center.z * 10.0) / 10.0);

  document()->undoStack()->undo();
  QVERIFY(log().board == start);
  QVERIFY(waitForFaces(rendered, 2));
  QVERIFY(changedShare(before, window_->facesView()->faces()[0]) < 0.001);  // the same board again
}

void TestLogView::typedPlacementIsOneUndoStep() {
  const int steps = document()->undoStack()->index();
  const Board start = log().board;
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  window_->boardControls()->spinBox(7)->setValue(start.rotationDeg.y + 30.0);  // turn about the log axis
  QCOMPARE(document()->undoStack()->index(), steps + 1);
  QVERIFY(std::abs(log().board.rotationDeg.y - (start.rotationDeg.y + 30.0f)) < 0.06f);
  window_->boardControls()->spinBox(5)->setValue(20.0);  // a thinner board: the block follows
  QCOMPARE(document()->project().block.size().z, 20.0f);
  QVERIFY(waitForFaces(rendered));
  QCOMPARE(window_->facesView()->block().size().z, 20.0f);
  document()->undoStack()->undo();
  document()->undoStack()->undo();
  QVERIFY(log().board == start);
  QCOMPARE(document()->project().block.size(), start.size);
}

void TestLogView::addsEditsAndDeletesKnots() {
  const std::vector<Knot> original = log().log.knots;
  const int steps = document()->undoStack()->index();
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  QVERIFY(waitForFaces(rendered, 0));
  const QImage before = window_->facesView()->faces()[0];

  // Add: a living branch at the board's height pointing at the board, so face A shows it.
  KnotTable* table = window_->knotTable();
  rendered.clear();
  QTest::mouseClick(table->findChild<QPushButton*>(), Qt::LeftButton);  // the first button: Add Knot
  QCOMPARE(log().log.knots.size(), original.size() + 1);
  QCOMPARE(document()->undoStack()->undoText(), QStringLiteral("Add knot"));
  const int added = static_cast<int>(original.size());
  QCOMPARE(table->selectedKnot(), added);
  QCOMPARE(window_->logView()->selectedKnot(), added);
  QVERIFY(waitForFaces(rendered));
  const double changed = changedShare(before, window_->facesView()->faces()[0]);
  qInfo("a knot added through the board changed %.1f %% of face A", 100.0 * changed);
  QVERIFY(changed > 0.01);

  // Edit: the rise, typed into the table, then the branch's death.
  const float z0 = log().log.knots[added].heightAt(60.0f);
  table->table()->item(added, KnotTable::Rise)->setData(Qt::EditRole, 0.8);
  QCOMPARE(document()->undoStack()->undoText(), QStringLiteral("Edit knot %1").arg(added + 1));
  QVERIFY(log().log.knots[added].heightAt(60.0f) > z0 + 10.0f);
  QVERIFY(std::abs(describeKnot(log().log.knots[added]).rise - 0.8f) < 1e-3f);
  QVERIFY(!std::isfinite(log().log.knots[added].deathDistance));
  table->table()->item(added, KnotTable::Dead)->setCheckState(Qt::Checked);
  QVERIFY(std::isfinite(log().log.knots[added].deathDistance));
  table->table()->item(added, KnotTable::DeathDistance)->setData(Qt::EditRole, 40.0);
  QCOMPARE(log().log.knots[added].deathDistance, 40.0f);

  // Delete the first knot of the log.
  table->setSelectedKnot(0);
  QTest::mouseClick(table->findChildren<QPushButton*>().at(1), Qt::LeftButton);
  QCOMPARE(log().log.knots.size(), original.size());
  QCOMPARE(document()->undoStack()->undoText(), QStringLiteral("Delete knot 1"));
  QCOMPARE(document()->undoStack()->index(), steps + 5);

  // Undo all five steps: the knots are exactly the log's own again.
  for (int i = 0; i < 5; ++i) document()->undoStack()->undo();
  QCOMPARE(log().log.knots.size(), original.size());
  for (std::size_t k = 0; k < original.size(); ++k) {
    QCOMPARE(log().log.knots[k].heights, original[k].heights);
    QCOMPARE(log().log.knots[k].azimuths, original[k].azimuths);
  }
  QCOMPARE(table->table()->rowCount(), static_cast<int>(original.size()));
  document()->undoStack()->redo();  // keep the added knot for the save test
  QCOMPARE(log().log.knots.size(), original.size() + 1);
}

void TestLogView::savesAndReopensProjectWithLog() {
  Board moved = log().board;
  moved.center.z += 25.0f;
  moved.rotationDeg = {0.0f, 12.5f, 3.0f};
  document()->editBoard(moved, true);
  const ProjectLog saved = log();
  const QString path = dir_.filePath("with_log.kerf");
  QVERIFY(window_->saveAs(path));
  const QString logPath = dir_.filePath("the.kerflog");
  QVERIFY(window_->logBoard()->saveLogAs(logPath));
  const LogModel alone = loadLogFile(logPath.toStdString());
  QCOMPARE(alone.knots.size(), saved.log.knots.size());

  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(path);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(document()->log().has_value());
  QVERIFY(log().board == saved.board);
  QCOMPARE(log().log.knots.size(), saved.log.knots.size());
  for (std::size_t k = 0; k < saved.log.knots.size(); ++k) {
    QCOMPARE(log().log.knots[k].heights, saved.log.knots[k].heights);
    QCOMPARE(log().log.knots[k].deathDistance, saved.log.knots[k].deathDistance);
  }
  QCOMPARE(log().log.stem.radii, saved.log.stem.radii);
  QCOMPARE(document()->undoStack()->count(), 0);
  QCOMPARE(window_->logView()->board().center, saved.board.center);
  QCOMPARE(document()->project().block.size(), saved.board.size);
  // The 3D view and the cut panel show the reopened board at once.
  QVERIFY(window_->viewport()->boardWood()->board == saved.board);
  QVERIFY(window_->cutView()->boardWood()->board == saved.board);
}

void TestLogView::closesLogAsUndoStep() {
  const ProjectLog before = log();
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  window_->logBoard()->closeLog();
  QVERIFY(!document()->log().has_value());
  QVERIFY(!window_->logView()->log());
  QVERIFY(waitForFaces(rendered));
  QVERIFY(window_->facesView()->hasFaces());  // the block's own model
  QVERIFY(!window_->viewport()->boardWood());
  QVERIFY(!window_->cutView()->boardWood());
  document()->undoStack()->undo();
  QVERIFY(window_->viewport()->boardWood());
  QVERIFY(document()->log().has_value());
  QVERIFY(log().board == before.board);
  QVERIFY(waitForFaces(rendered, 2));
}

namespace {

// Both GL views drawn completely at full resolution, as they are now.
QImage grabCut(CutView* cut) {
  cut->setForcedRenderScale(1);
  return cut->grabFramebuffer();
}
QImage grab3d(Viewport3D* viewport) {
  viewport->refineNow();
  return viewport->grabFramebuffer();
}

// changedShare over the wood of the cut panel only (inside the cut's outline).
double changedShareOnCut(const QImage& a, const QImage& b, const CutView* cut) {
  const QPolygonF outline = cut->cutOutline();
  const QRect box = outline.boundingRect().toAlignedRect().intersected(a.rect());
  int changed = 0, inside = 0;
  for (int y = box.top(); y <= box.bottom(); ++y)
    for (int x = box.left(); x <= box.right(); ++x) {
      if (!outline.containsPoint(QPointF(x + 0.5, y + 0.5), Qt::OddEvenFill)) continue;
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      changed +=
          std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q)) > 24;
      ++inside;
    }
  return inside > 0 ? static_cast<double>(changed) / inside : 0.0;
}

}  // namespace

void TestLogView::cutAndThreeDShowTheLogsWood() {
  Viewport3D* viewport = window_->viewport();
  CutView* cut = window_->cutView();
  if (auto* dock = window_->findChild<QDockWidget*>("cutDock")) dock->raise();
  QTest::qWait(50);
  const std::shared_ptr<const BoardWood> wood = viewport->boardWood();
  QVERIFY(wood);
  QVERIFY(wood->board == log().board);
  document()->setCutEnabled(true);
  CutPlaneSetting setting;
  setting.azimuthDeg = 30.0f, setting.elevationDeg = 25.0f, setting.offsetMm = 3.0f;
  document()->editCutPlane(setting, true);
  QVERIFY(viewport->cutEnabled());
  QVERIFY(cut->plane().has_value());
  cut->zoomToFit();
  const QImage logCut = grabCut(cut), log3d = grab3d(viewport);
  const QString dir = QStringLiteral(KERF_TEST_ARTIFACTS_DIR);
  QVERIFY(QDir().mkpath(dir));
  QVERIFY(logCut.save(dir + "/log_cut_panel.png"));
  QVERIFY(log3d.save(dir + "/log_viewport3d.png"));

  // The cut panel shows the board's field: its pixels are core's colours at the block points under them.
  int samples = 0, close = 0;
  double sum = 0;
  for (int y = 4; y < cut->height(); y += 5)
    for (int x = 3; x < cut->width(); x += 7) {
      const QPointF at(x + 0.5, y + 0.5);
      const auto p = cut->blockPointAt(at);
      if (!p || cut->bottomRulerRect().contains(at) || cut->leftRulerRect().contains(at)) continue;
      const glm::vec3 c = boardWoodColor(*wood, *p);
      const QColor shown =
          logCut.pixelColor(qRound(x * logCut.devicePixelRatio()), qRound(y * logCut.devicePixelRatio()));
      const double d =
          (std::abs(shown.redF() - c.x) + std::abs(shown.greenF() - c.y) + std::abs(shown.blueF() - c.z)) / 3;
      sum += d;
      close += d < 0.03;
      ++samples;
    }
  qInfo("cut panel against core's board wood: %d samples, mean |difference| %.4f, %.1f %% within 0.03",
        samples, sum / std::max(samples, 1), 100.0 * close / std::max(samples, 1));
  QVERIFY(samples > 150);
  QVERIFY(sum / samples < 0.02);
  QVERIFY(close > 0.9 * samples);

  // Not the block's procedural model: the same views without the board's wood look different.
  viewport->setBoardWood(nullptr);
  cut->setBoardWood(nullptr);
  const QImage blockCut = grabCut(cut), block3d = grab3d(viewport);
  viewport->setBoardWood(wood);
  cut->setBoardWood(wood);
  QVERIFY(blockCut.save(dir + "/log_cut_panel_block_model.png"));
  const double cutVsBlock = changedShareOnCut(logCut, blockCut, cut),
               viewVsBlock = changedShare(log3d, block3d);
  qInfo("log wood against the block model: cut panel %.1f %%, 3D view %.1f %% of pixels differ",
        100 * cutVsBlock, 100 * viewVsBlock);
  QVERIFY(cutVsBlock > 0.3);
  QVERIFY(viewVsBlock > 0.06);                          // the board covers about a quarter of the view
  QVERIFY(changedShare(logCut, grabCut(cut)) < 0.001);  // and back

  // Moving the cut plane and moving the board through the log change both views.
  setting.offsetMm += 6.0f;
  document()->editCutPlane(setting, true);
  const QImage movedCut = grabCut(cut);
  const double cutMoved = changedShareOnCut(logCut, movedCut, cut);
  Board moved = log().board;
  moved.center.z += 40.0f;
  QSignalSpy facesRendered(window_.get(), &MainWindow::facesRendered);
  document()->editBoard(moved, true);
  QVERIFY(viewport->boardWood()->board == moved);
  QCOMPARE(cut->boardWood(), viewport->boardWood());
  QVERIFY(viewport->boardWood()->field == wood->field);  // a board move keeps the knot field
  const QImage boardCut = grabCut(cut), board3d = grab3d(viewport);
  QVERIFY(boardCut.save(dir + "/log_cut_panel_board_moved.png"));
  const double boardMovedCut = changedShareOnCut(movedCut, boardCut, cut),
               boardMoved3d = changedShare(log3d, board3d);
  qInfo("cut moved 6 mm: %.1f %%; board moved 40 mm up the log: cut panel %.1f %%, 3D view %.1f %% changed",
        100 * cutMoved, 100 * boardMovedCut, 100 * boardMoved3d);
  QVERIFY(cutMoved > 0.2);
  QVERIFY(boardMovedCut > 0.2);
  QVERIFY(boardMoved3d > 0.06);
  QVERIFY(waitForFaces(facesRendered));  // the window's picture with the faces of the moved board
  QVERIFY(grabWindowWithGl(window_.get()).save(dir + "/log_mode_cut.png"));

  cut->setForcedRenderScale(0);
  document()->undoStack()->undo();  // the board
  document()->undoStack()->undo();  // the second cut
  document()->setCutEnabled(false);
}

// CLT, plywood and veneer of the open log in the Panel view: the pictures of kerf-cli render-panel.
void TestLogView::showsPanelsFromTheLog() {
  PanelControls* controls = window_->panelControls();
  ImagePane* pane = window_->panelPane();
  QVERIFY(controls && pane);
  QSignalSpy rendered(window_.get(), &MainWindow::panelRendered);
  struct Case {
    PanelType type;
    const char* caption;
    double aspect;  // width / height of the picture
  };
  const Case cases[] = {{PanelType::Clt, "CLT panel, 3 layers, face A", 1.0},
                        {PanelType::Plywood, "plywood, 5 plies, face A", 1.0},
                        {PanelType::Veneer, "rotary-cut veneer", 2.0}};
  QImage previous;
  for (const Case& c : cases) {
    controls->setType(c.type);
    controls->showButton()->click();
    const int count = static_cast<int>(rendered.count());
    QVERIFY(QTest::qWaitFor([&] { return rendered.count() > count; }, kTimeoutMs));
    const QImage image = pane->image();
    QVERIFY(!image.isNull());
    QVERIFY2(pane->caption().startsWith(c.caption), qPrintable(pane->caption()));
    QCOMPARE(std::max(image.width(), image.height()), 1200);
    QVERIFY(std::abs(double(image.width()) / image.height() - c.aspect) < 0.01);
    if (!previous.isNull() && previous.size() == image.size()) QVERIFY(changedShare(previous, image) > 0.3);
    previous = image;
    QVERIFY(image.save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/log_panel_%1.png").arg(int(c.type))));
  }
  auto* dock = window_->findChild<QDockWidget*>("panelDock");
  QVERIFY(dock && dock->isVisible());
  if (auto* tabs = window_->findChild<QTabWidget*>("boardTabs")) tabs->setCurrentIndex(1);
  QVERIFY(
      grabWindowWithGl(window_.get()).save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/log_panel_window.png")));
  if (auto* logViewDock = window_->findChild<QDockWidget*>("logViewDock")) logViewDock->raise();
  if (auto* tabs = window_->findChild<QTabWidget*>("boardTabs")) tabs->setCurrentIndex(0);
}

void TestLogView::savesScreenshot() {
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  if (auto* dock = window_->findChild<QDockWidget*>("logViewDock")) dock->raise();
  if (auto* dock = window_->findChild<QDockWidget*>("boardDock")) dock->raise();
  window_->knotTable()->setSelectedKnot(2);
  window_->logView()->setSelectedKnot(2);
  window_->viewport()->refineNow();
  QTest::qWait(800);
  const QString path = QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/log_view.png");
  QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
  const QImage shot = grabWindowWithGl(window_.get());
  QVERIFY(shot.save(path));
  const QByteArray extra = qgetenv("KERF_LOG_SCREENSHOT");
  if (!extra.isEmpty()) QVERIFY(shot.save(QString::fromUtf8(extra)));
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  TestLogView test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_log_view.moc"
