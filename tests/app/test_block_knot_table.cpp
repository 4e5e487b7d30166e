// The block's knot table (docs/editor.md, "Knots in the block"): on the demo block with its knot, the
// "Knots" dock shows it; ticking Dead and typing a death kill the knot in the document, one undo step
// each, and the faces show it (the pixels around the knot change, and come back with undo); a death
// before the knot starts is refused at its cell; a row selects its knot's marks and the marks their row;
// Del deletes the knot with undo and Space ticks Dead; the table follows a fit that adds knots; the knots'
// edits survive a save and reopen. Saves the editor at 1366 x 768 with the table (block_knot_table.png).
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <cmath>

#include "annotation_layer.hpp"
#include "block_knot_table.hpp"
#include "cut_view.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "field/block_knot_shape.hpp"
#include "fit_job.hpp"
#include "gpu/surface_format.hpp"
#include "image_change.hpp"
#include "main_window.hpp"
#include "rings_controller.hpp"
#include "viewport3d.hpp"
#include "window_grab.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 120000;
}  // namespace

class TestBlockKnotTable : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void showsTheDemoKnot();
  void deathInTheTableKillsTheKnotWithUndo();
  void refusesADeathBeforeTheKnotStarts();
  void angleEditTurnsTheKnot();
  void rowSelectsItsMarksAndMarksTheirRow();
  void deleteKeyDeletesTheKnotWithUndo();
  void followsAFitThatAddsKnots();
  void roundTripsThroughTheProjectFile();
  void savesScreenshot();
  void cleanupTestCase() { window_.reset(); }

 private:
  Document* document() const { return window_->document(); }
  BlockKnotTable* table() const { return window_->blockKnotTable(); }
  QTableWidgetItem* cell(int row, int column) const { return table()->table()->item(row, column); }
  bool waitForFaces(QSignalSpy& rendered, int count = 1) {
    return QTest::qWaitFor([&] { return rendered.count() >= count && !window_->isBusy(); }, kTimeoutMs);
  }
  // The model's faces where the knot comes out of the block: a square of twice the knot's diameter around
  // where its axis crosses face `crossing.face`.
  QImage aroundKnot(const KnotCrossing& crossing) const {
    const QImage& face = window_->facesView()->renderings()[faceIndex(crossing.face)];
    const Block& block = document()->project().block;
    const glm::vec2 at = block.blockToImage(crossing.face, crossing.point, {face.width(), face.height()});
    const float pxPerMm = face.width() / block.face(crossing.face).widthMm;
    const int half = std::max(3, static_cast<int>(std::ceil(crossing.diameterMm * pxPerMm)));
    return face.copy(static_cast<int>(at.x) - half, static_cast<int>(at.y) - half, 2 * half, 2 * half);
  }
  std::vector<KnotCrossing> crossings() const {
    const auto model = document()->model();
    return knotCrossings(document()->project().knots.at(0), model->block(), model->field(),
                         model->knots().settings());
  }

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestBlockKnotTable::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.filePath("settings"));
  QSettings().clear();  // the default layout
  window_ = testing::openDemoWindow(dir_.filePath("knotty"), 64, QSize(1366, 768), kTimeoutMs, true);
  QVERIFY(window_);
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  QVERIFY(waitForFaces(rendered, 0));
  QCOMPARE(document()->project().knots.size(), 1u);
}

void TestBlockKnotTable::showsTheDemoKnot() {
  auto* dock = window_->findChild<QDockWidget*>("blockKnotsDock");
  QVERIFY(dock);
  QVERIFY(dock->isVisibleTo(window_.get()));  // a tab beside the parameters
  QCOMPARE(table()->table()->rowCount(), 1);
  QCOMPARE(cell(0, BlockKnotTable::Id)->text(), QStringLiteral("K1"));  // as its marks
  // The demo's knot leans up along the pith: about 76 degrees to it (addDemoKnot).
  const double angle = cell(0, BlockKnotTable::Angle)->data(Qt::EditRole).toDouble();
  QVERIFY2(angle > 70 && angle < 80, qPrintable(QString::number(angle)));
  QCOMPARE(cell(0, BlockKnotTable::Dead)->checkState(), Qt::Unchecked);
  QVERIFY(!(cell(0, BlockKnotTable::DiedAt)->flags() & Qt::ItemIsEditable));
  // It comes out on two faces, each with its diameter there.
  QCOMPARE(crossings().size(), 2u);
  QCOMPARE(cell(0, BlockKnotTable::Faces)->text().count(QStringLiteral("·")), 1);
  for (int c = 0; c < BlockKnotTable::ColumnCount; ++c)
    QVERIFY(!table()->table()->horizontalHeaderItem(c)->toolTip().isEmpty());
}

void TestBlockKnotTable::deathInTheTableKillsTheKnotWithUndo() {
  const std::vector<KnotCrossing> out = crossings();
  QCOMPARE(out.size(), 2u);
  const std::array<QImage, 2> before = {aroundKnot(out[0]), aroundKnot(out[1])};
  const int steps = document()->undoStack()->index();

  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  cell(0, BlockKnotTable::Dead)->setCheckState(Qt::Checked);  // as a click or Space on the box
  QVERIFY(document()->project().knots[0].dead());
  QCOMPARE(document()->undoStack()->index(), steps + 1);
  QCOMPARE(document()->undoStack()->undoText(), QStringLiteral("Edit knot K1"));
  QVERIFY(cell(0, BlockKnotTable::DiedAt)->flags() & Qt::ItemIsEditable);
  // Dead before it reaches the block: the knot is dead on both faces.
  const double death = 0.5 * std::min(out[0].stemYears, out[1].stemYears);
  cell(0, BlockKnotTable::DiedAt)->setData(Qt::EditRole, death);
  QCOMPARE(document()->undoStack()->index(), steps + 2);
  QCOMPARE(document()->project().knots[0].deathTime, static_cast<float>(death));
  QCOMPARE(cell(0, BlockKnotTable::Dead)->checkState(), Qt::Checked);
  // The views have the dead knot's model, and the faces show it: pixels around the knot differ.
  QCOMPARE(window_->viewport()->model(), document()->model());
  QCOMPARE(window_->cutView()->model(), document()->model());
  QVERIFY(waitForFaces(rendered));
  QVERIFY(QDir().mkpath(KERF_TEST_ARTIFACTS_DIR));
  for (int i = 0; i < 2; ++i) {  // to look at: alive | dead, around where the knot comes out
    const QImage after = aroundKnot(out[i]);
    QImage pair(2 * after.width() + 1, after.height(), QImage::Format_RGB32);
    pair.fill(Qt::black);
    for (int y = 0; y < after.height(); ++y)
      for (int x = 0; x < after.width(); ++x) {
        pair.setPixel(x, y, before[i].pixel(x, y));
        pair.setPixel(after.width() + 1 + x, y, after.pixel(x, y));
      }
    QVERIFY(pair.scaled(pair.size() * 8)
                .save(testing::artifact(
                    QStringLiteral("block_knot_death_%1").arg(QChar(faceLetter(out[i].face))))));
  }
  for (int i = 0; i < 2; ++i) {
    const double changed = testing::changedShare(before[i], aroundKnot(out[i]));
    qInfo("face %c: %.1f %% of the pixels around the knot changed with its death", faceLetter(out[i].face),
          100 * changed);
    QVERIFY2(changed > 0.05, qPrintable(QString::number(changed)));
  }

  // Undo twice: alive again, and the faces as they were.
  rendered.clear();
  document()->undoStack()->undo();
  document()->undoStack()->undo();
  QVERIFY(!document()->project().knots[0].dead());
  QCOMPARE(cell(0, BlockKnotTable::Dead)->checkState(), Qt::Unchecked);
  QVERIFY(waitForFaces(rendered));
  for (int i = 0; i < 2; ++i) QVERIFY(testing::changedShare(before[i], aroundKnot(out[i])) < 0.01);
  // Redo: dead again, at the typed death.
  document()->undoStack()->redo();
  document()->undoStack()->redo();
  QVERIFY(document()->project().knots[0].dead());
  QCOMPARE(cell(0, BlockKnotTable::DiedAt)->data(Qt::EditRole).toDouble(), std::round(death * 100) / 100);
}

void TestBlockKnotTable::refusesADeathBeforeTheKnotStarts() {
  QVERIFY(document()->project().knots[0].dead());
  const float death = document()->project().knots[0].deathTime;
  const int steps = document()->undoStack()->index();
  cell(0, BlockKnotTable::DiedAt)->setData(Qt::EditRole, -3.0);
  QCOMPARE(document()->undoStack()->index(), steps);
  QCOMPARE(document()->project().knots[0].deathTime, death);
  QVERIFY2(table()->lastRefusal().contains(QStringLiteral("before it starts")),
           qPrintable(table()->lastRefusal()));
  QCOMPARE(cell(0, BlockKnotTable::DiedAt)->data(Qt::EditRole).toDouble(), std::round(death * 100.0) / 100.0);
  // A growth of 1.5 is refused too: a branch thickens slower than the stem.
  cell(0, BlockKnotTable::Speed)->setData(Qt::EditRole, 1.5);
  QCOMPARE(document()->undoStack()->index(), steps);
  QVERIFY(table()->lastRefusal().contains(QStringLiteral("between 0 and 1")));
}

void TestBlockKnotTable::angleEditTurnsTheKnot() {
  const BlockKnot before = document()->project().knots[0];
  const PithAxis pith = document()->model()->field().axis();
  cell(0, BlockKnotTable::Angle)->setData(Qt::EditRole, 90.0);
  const BlockKnot after = document()->project().knots[0];
  QVERIFY(std::abs(glm::dot(after.direction, pith.direction)) < 1e-4f);  // straight out of the stem
  QCOMPARE(after.origin, before.origin);
  QCOMPARE(describeBlockKnot(after, pith).aroundDeg, describeBlockKnot(before, pith).aroundDeg);
  document()->undoStack()->undo();
  QCOMPARE(document()->project().knots[0], before);
  // Typed in the cell's editor, with three decimals.
  QTableWidget* t = table()->table();
  t->setCurrentCell(0, BlockKnotTable::Speed);
  t->editItem(cell(0, BlockKnotTable::Speed));
  auto* box = t->viewport()->findChild<QDoubleSpinBox*>();
  QVERIFY(box);
  box->setValue(0.075);
  QTest::keyClick(box, Qt::Key_Return);  // the delegate commits from the event loop
  QTRY_COMPARE_WITH_TIMEOUT(document()->project().knots[0].speed, 0.075f, kTimeoutMs);
  document()->undoStack()->undo();
  QCOMPARE(document()->project().knots[0], before);
}

void TestBlockKnotTable::rowSelectsItsMarksAndMarksTheirRow() {
  AnnotationLayer* layer = window_->annotationLayer();
  QCOMPARE(document()->annotations().knots.size(), 2u);  // the demo's two marks of knot 0
  table()->setSelectedKnot(-1);
  layer->clearSelection();
  table()->table()->selectRow(0);  // as a click on the row
  QCOMPARE(layer->selectedKnots(), (std::vector<std::size_t>{0, 1}));
  // The marks deselected on the faces, a click on the still selected row selects them again.
  layer->clearSelection();
  QTableWidget* t = table()->table();
  QTest::mouseClick(t->viewport(), Qt::LeftButton, {},
                    t->visualRect(t->model()->index(0, BlockKnotTable::Angle)).center());
  QCOMPARE(layer->selectedKnots(), (std::vector<std::size_t>{0, 1}));
  table()->setSelectedKnot(-1);
  layer->setSelection({}, {1});  // one mark picked on the faces
  QCOMPARE(table()->selectedKnot(), 0);
}

void TestBlockKnotTable::deleteKeyDeletesTheKnotWithUndo() {
  const std::vector<BlockKnot> before = document()->project().knots;
  window_->activateWindow();
  QVERIFY(QTest::qWaitForWindowActive(window_.get()));
  table()->table()->setFocus();
  table()->table()->selectRow(0);
  QTest::keyClick(table()->table(), Qt::Key_Delete);
  QVERIFY(document()->project().knots.empty());
  QCOMPARE(table()->table()->rowCount(), 0);
  QCOMPARE(document()->annotations().knots.size(), 2u);  // the marks stay
  QCOMPARE(document()->undoStack()->undoText(), QStringLiteral("Delete knot K1"));
  document()->undoStack()->undo();
  QCOMPARE(document()->project().knots, before);
  QCOMPARE(table()->table()->rowCount(), 1);
  // Space on the Dead box lets the knot die (and live again), one undo step each.
  const bool dead = before[0].dead();
  table()->table()->setFocus();
  table()->table()->setCurrentCell(0, BlockKnotTable::Dead);
  QTest::keyClick(table()->table(), Qt::Key_Space);
  QCOMPARE(document()->project().knots[0].dead(), !dead);
  document()->undoStack()->undo();
  QCOMPARE(document()->project().knots, before);
}

void TestBlockKnotTable::followsAFitThatAddsKnots() {
  // A fit's result lands through RingsController::applyFit, as after Fit Growth Field.
  const Project& p = document()->project();
  auto fit = std::make_shared<GrowthFitResult>();
  fit->params = p.params;
  fit->rates = document()->model()->field().rates();
  BlockKnot second = p.knots[0];
  second.id = 1;
  second.origin += 8.0f * document()->model()->field().axis().direction;
  second.speed = 0.12f;
  fit->knots = {p.knots[0], second};
  QVERIFY(window_->rings()->applyFit(fit));
  QCOMPARE(table()->table()->rowCount(), 2);
  QCOMPARE(cell(1, BlockKnotTable::Id)->text(), QStringLiteral("K2"));
  QCOMPARE(cell(1, BlockKnotTable::Speed)->data(Qt::EditRole).toDouble(), 0.12);
  document()->undoStack()->undo();
  QCOMPARE(table()->table()->rowCount(), 1);
  document()->undoStack()->redo();
  QCOMPARE(table()->table()->rowCount(), 2);
}

void TestBlockKnotTable::roundTripsThroughTheProjectFile() {
  // Knot 1 dies at 7.5 years and tapers; saved and opened again, the table shows the same.
  cell(1, BlockKnotTable::Taper)->setData(Qt::EditRole, 0.3);
  cell(1, BlockKnotTable::Dead)->setCheckState(Qt::Checked);
  cell(1, BlockKnotTable::DiedAt)->setData(Qt::EditRole, 7.5);
  const std::vector<BlockKnot> knots = document()->project().knots;
  QCOMPARE(knots[1].deathTime, 7.5f);
  QCOMPARE(knots[1].taper, 0.3f);
  const QString path = dir_.filePath("knots.kerf");
  QVERIFY(window_->saveAs(path));
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(path);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QCOMPARE(document()->project().knots.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const BlockKnot& k = document()->project().knots[i];
    QCOMPARE(k.id, knots[i].id);
    QCOMPARE(k.deathTime, knots[i].deathTime);
    QCOMPARE(k.taper, knots[i].taper);
    QVERIFY(glm::length(k.origin - knots[i].origin) < 1e-4f);
  }
  QCOMPARE(table()->table()->rowCount(), 2);
  QCOMPARE(cell(1, BlockKnotTable::DiedAt)->data(Qt::EditRole).toDouble(), 7.5);
  QCOMPARE(document()->undoStack()->count(), 0);
}

void TestBlockKnotTable::savesScreenshot() {
  // The demo's own knot, dead half way, its row selected (its marks selected on the faces), the Knots tab
  // raised: the layout at 1366 x 768 keeps the wood's share.
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  window_->openDocument(dir_.filePath("knotty/demo.kerf"));
  QVERIFY(waitForFaces(rendered));
  auto* dock = window_->findChild<QDockWidget*>("blockKnotsDock");
  dock->raise();
  window_->toggleViewAction()->trigger();  // the faces show the model: the dead knot's bark ring
  cell(0, BlockKnotTable::Dead)->setCheckState(Qt::Checked);
  QVERIFY(waitForFaces(rendered, 2));
  table()->setSelectedKnot(-1);
  table()->table()->selectRow(0);  // and with it the knot's marks
  QCOMPARE(window_->annotationLayer()->selectedKnots().size(), 2u);
  window_->viewport()->refineNow();
  window_->statusBar()->clearMessage();
  QTest::qWait(200);
  QVERIFY(QDir().mkpath(KERF_TEST_ARTIFACTS_DIR));
  QVERIFY(grabWindowWithGl(window_.get()).save(testing::artifact(QStringLiteral("block_knot_table"))));
  QCOMPARE(window_->size(), QSize(1366, 768));
  double wood = 0;
  for (const QWidget* view :
       {static_cast<const QWidget*>(window_->facesView()), static_cast<const QWidget*>(window_->viewport()),
        static_cast<const QWidget*>(window_->cutView())})
    wood += view->isVisible() ? double(view->width()) * view->height() : 0.0;
  wood /= double(window_->width()) * window_->height();
  qInfo("the wood covers %.1f %% of the window with the Knots tab raised", 100 * wood);
  QVERIFY(wood > 0.5);
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  TestBlockKnotTable test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_block_knot_table.moc"
