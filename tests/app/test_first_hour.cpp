// A woodworker's first hour (issue 20, "Must show"): from an empty editor to a cut preview on CN03's six
// photos alone (a temporary copy of ../shared/data/mokume/CN03/X_col.png, nothing else), as a user would:
// the start page, Open Photos (the block shows the photos), Reconstruct (Ctrl+R: the rings land on the faces,
// then the field, then the wood, each stage named in the status bar), and the cut. A screenshot at every
// step (walkthrough_N_*.png; docs/editor.md shows them). Every wait is on a signal, never on the clock.
// Also: the start page lists recent files; Reconstruct is refused without photos and, stopped at once,
// changes nothing; the fit's quality in words.
#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <QMessageBox>
#include "cut_view.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "fit_quality.hpp"
#include "gpu/surface_format.hpp"
#include "job_runner.hpp"
#include "log_panel.hpp"
#include "main_window.hpp"
#include "parameter_panel.hpp"
#include "params/builtin_presets.hpp"
#include "quick_texture_options.hpp"
#include "start_page.hpp"
#include "viewport3d.hpp"
#include "window_grab.hpp"
#include "work_path.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 240000;  // a ceiling for a stuck job, not a measure: every wait ends on a signal
const QString kSample = QStringLiteral(KERF_SHARED_DIR "/data/mokume/CN03");

}  // namespace

class TestFirstHour : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void fitInWords();
  void startPageOffersTheWayIn();
  void reconstructNeedsPhotos();
  void walkthroughFromPhotosToCut();
  void stoppedAtOnceChangesNothing();
  void planReconstructRerunsWhatDependsOnTheChange();
  void aCorrectedRingRefitsWithoutDetectingAgain();
  void cleanupTestCase() { window_.reset(); }

 private:
  void shoot(const QString& name) {
    window_->viewport()->refineNow();
    QVERIFY(grabWindowWithGl(window_.get()).save(testing::artifact(name)));
  }

  QTemporaryDir dir_;
  QString photos_;
  std::unique_ptr<MainWindow> window_;
};

void TestFirstHour::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.filePath("settings"));
  QSettings().clear();
  QVERIFY(QDir().mkpath(KERF_TEST_ARTIFACTS_DIR));
  window_ = std::make_unique<MainWindow>(RenderSettings{6.4f, 1});  // 256 px faces, as CN03's photos
  window_->setAskBeforeDiscarding(false);
  // A short appearance stage (still a real inference with previews); the core's defaults take minutes.
  window_->texture()->setTextureOptions(testing::quickTextureOptions());
  window_->resize(1366, 768);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TestFirstHour::fitInWords() {
  QCOMPARE(gradeFit(0.02), FitGrade::Close);
  QCOMPARE(gradeFit(0.047), FitGrade::Good);
  QCOMPARE(gradeFit(0.15), FitGrade::Rough);
  QCOMPARE(gradeFit(0.5), FitGrade::Poor);
  QCOMPARE(gradeFit(std::nan("")), FitGrade::Poor);
  QCOMPARE(summarizeFit(0.047, false), QStringLiteral("Fit: good, rings off by 5 % of a ring width"));
  QCOMPARE(summarizeFit(0.3, true),
           QStringLiteral("Fit: poor, rings off by 30 % of a ring width; pith side unsure"));
  QVERIFY(explainFit(0.15, false).contains(QStringLiteral("Show Fit Residuals")));
}

// Empty start: the start page where the faces go, with its three ways in and the recent files.
void TestFirstHour::startPageOffersTheWayIn() {
  WorkPath* path = window_->workPath();
  QVERIFY(path->showingStartPage());
  StartPage* page = path->startPage();
  QVERIFY(page->isVisible());
  for (QPushButton* button : {page->photosButton(), page->projectButton(), page->demoButton()}) {
    QVERIFY(button->isVisible());
    QVERIFY(!button->toolTip().isEmpty());
  }
  QVERIFY(!path->reconstructAction()->isEnabled());  // nothing to reconstruct yet
  shoot(QStringLiteral("walkthrough_1_start"));
}

void TestFirstHour::reconstructNeedsPhotos() {
  QSignalSpy failed(window_->workPath(), &WorkPath::reconstructFailed);
  window_->workPath()->reconstruct();
  QCOMPARE(failed.count(), 1);
  QVERIFY(failed.front().front().toString().contains(QStringLiteral("photos")));
  QVERIFY(!window_->isBusy());
  // The message box that said so (window-modal) is closed, as the user would.
  for (QMessageBox* box : window_->findChildren<QMessageBox*>()) box->close();
  window_->log()->clear();  // and the log's error badge with it: the walkthrough starts clean
}

void TestFirstHour::walkthroughFromPhotosToCut() {
  if (!QFileInfo::exists(kSample + "/A_col.png"))
    QSKIP(qPrintable(
        QStringLiteral("%1 is absent (../shared is not checked out): no walkthrough on CN03").arg(kSample)));
  // CN03's six photos alone: no ring images, no traces, no project.
  photos_ = dir_.filePath("CN03");
  QVERIFY(QDir().mkpath(photos_));
  for (const char face : {'A', 'B', 'C', 'D', 'E', 'F'}) {
    const QString name = QStringLiteral("%1_col.png").arg(face);
    QVERIFY(QFile::copy(kSample + "/" + name, photos_ + "/" + name));
  }

  // 2. Open Photos: the faces show the photos, and so does the 3D block (no wood is fitted yet).
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->workPath()->openPhotos(photos_);
  QVERIFY(QTest::qWaitFor([&] { return ready.count() > 0; }, kTimeoutMs));
  QVERIFY(!window_->workPath()->showingStartPage());
  QVERIFY(window_->showingPhotos());
  QVERIFY(window_->viewport()->showPhotos());
  QVERIFY(window_->document()->cutEnabled());  // a default cut, shown
  QVERIFY(window_->findChild<QDockWidget*>("cutDock")->isVisible());
  QVERIFY(window_->workPath()->reconstructAction()->isEnabled());
  QVERIFY(window_->workPath()->fitLabel()->text().isEmpty());
  // The folder's Mokume code (CN03: kuri, chestnut) chooses the species the wood starts from, as in
  // `kerf-cli fit`: without it the reconstruction showed the default wood's scattered dark pores.
  QCOMPARE(window_->parameterPanel()->presetBox()->currentText().contains("kuri"), true);
  QCOMPARE(window_->document()->project().params.poreCellSize,
           builtInPreset("kuri")->parametersOnDefaults().poreCellSize);
  shoot(QStringLiteral("walkthrough_2_photos"));

  // 3-5. Reconstruct (Ctrl+R). Each stage is named in the status bar while it runs, and its result is on
  // screen when it lands: the screenshots are taken right then, before the next stage's results arrive.
  QList<ReconstructStage> started, landed;
  QStringList stageNames;
  WorkPath* path = window_->workPath();
  QObject scope;  // the lambdas below capture this function's locals: disconnected when it returns
  connect(path, &WorkPath::stageStarted, &scope, [&](ReconstructStage stage) {
    started << stage;
    stageNames << window_->workPath()->fitLabel()->text();
  });
  connect(path, &WorkPath::stageLanded, &scope, [&](ReconstructStage stage) {
    landed << stage;
    if (stage == ReconstructStage::Rings) {
      // The rings, the document's detected traces, drawn over the photos.
      QVERIFY(!window_->document()->annotations().traces.empty());
      QVERIFY(window_->showContoursAction()->isChecked());
      shoot(QStringLiteral("walkthrough_3_rings"));
    } else if (stage == ReconstructStage::Field) {
      QVERIFY(!window_->viewport()->showPhotos());  // the block shows the fitted field now
      QCOMPARE(window_->facesView()->display(), FaceDisplay::Split);
      shoot(QStringLiteral("walkthrough_4_field"));
    }
  });
  QSignalSpy done(path, &WorkPath::reconstructed);
  QSignalSpy failed(path, &WorkPath::reconstructFailed);
  QSignalSpy rendered(window_.get(), &MainWindow::facesRendered);
  window_->activateWindow();
  QApplication::setActiveWindow(window_.get());
  QTRY_VERIFY_WITH_TIMEOUT(window_->isActiveWindow(),
                           kTimeoutMs);  // shortcuts need the active window (xvfb has no window manager)
  QTest::keyClick(window_.get(), Qt::Key_R, Qt::ControlModifier);
  QVERIFY2(path->isRunning(), qPrintable(failed.isEmpty() ? QStringLiteral("Ctrl+R did not start it")
                                                          : failed.front().front().toString()));
  QCOMPARE(path->reconstructAction()->text().remove('&'), QStringLiteral("Stop Reconstruct"));
  QVERIFY(QTest::qWaitFor([&] { return done.count() + failed.count() > 0; }, kTimeoutMs));
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  const QList<ReconstructStage> all = {ReconstructStage::Rings, ReconstructStage::Field,
                                       ReconstructStage::Appearance};
  QCOMPARE(started, all);
  QCOMPARE(landed, all);
  QCOMPARE(stageNames.size(), 3);
  for (int i = 0; i < 3; ++i)
    QVERIFY2(stageNames[i].startsWith(QStringLiteral("Reconstruct %1/3").arg(i + 1)),
             qPrintable(stageNames[i]));

  // The document: detected traces, the fitted field, the inferred wood, each one undo step.
  Document* document = window_->document();
  QVERIFY(!document->annotations().traces.empty());
  QVERIFY(document->project().rates.has_value());
  QUndoStack* undo = document->undoStack();
  QCOMPARE(undo->count(), 3);
  QVERIFY(undo->text(0).startsWith(QStringLiteral("Detect rings")));
  QCOMPARE(undo->text(1), QStringLiteral("Fit growth field"));
  QCOMPARE(undo->text(2), QStringLiteral("Infer texture"));
  // The status bar says how good the fit is, in words.
  const QString fit = path->fitLabel()->text();
  QVERIFY2(fit.startsWith(QStringLiteral("Fit: ")), qPrintable(fit));
  QVERIFY(!path->fitLabel()->toolTip().isEmpty());
  qInfo("%s", qPrintable(fit));
  // 6. The cut, shown at true scale; the faces rendered with the wood.
  QVERIFY(document->cutEnabled());
  QVERIFY(window_->cutView()->isVisible());
  QVERIFY(window_->viewport()->cutEnabled());
  QCOMPARE(path->reconstructAction()->text().remove('&'), QStringLiteral("Reconstruct"));
  rendered.clear();
  QVERIFY(QTest::qWaitFor([&] { return rendered.count() > 0 || !window_->isBusy(); }, kTimeoutMs));
  QVERIFY(QTest::qWaitFor([&] { return !window_->isBusy(); }, kTimeoutMs));
  shoot(QStringLiteral("walkthrough_5_cut"));
  // 7. How sure the fit is: estimated in the background once the wood has landed, said in the status bar,
  // and drawn over the cut on demand (U).
  const RingUncertainty* sure = document->ringUncertainty();
  QVERIFY2(sure, qPrintable(window_->log()->text().right(600)));
  QVERIFY(sure->quantile(0.5) > 0.0f);
  const QString withSure = path->fitLabel()->text();
  QVERIFY2(withSure.contains(QStringLiteral("inside the block ±")), qPrintable(withSure));
  qInfo("%s", qPrintable(withSure));
  QVERIFY(window_->cutView()->ringUncertainty());
  QVERIFY(!window_->cutView()->showsRingUncertainty());
  window_->cutView()->showRingUncertaintyAction()->trigger();
  QVERIFY(window_->cutView()->showsRingUncertainty());
  QTest::qWait(50);
  shoot(QStringLiteral("walkthrough_6_how_sure"));
  window_->cutView()->showRingUncertaintyAction()->trigger();
  // Undoing the fit hides it (it belongs to that field); redoing brings it back.
  undo->undo();
  undo->undo();
  QVERIFY(!document->ringUncertainty());
  QVERIFY(!window_->cutView()->ringUncertainty());
  undo->redo();
  undo->redo();
  QVERIFY(document->ringUncertainty());
  QVERIFY(window_->cutView()->ringUncertainty());
  QFile log(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/walkthrough_log.txt"));
  QVERIFY(log.open(QIODevice::WriteOnly));
  log.write(window_->log()->text().toUtf8());
}

// Stopped at once: nothing lands, the document is as it was.
void TestFirstHour::stoppedAtOnceChangesNothing() {
  if (!window_->document()->hasPhotos()) QSKIP("needs the walkthrough's photos (../shared is absent)");
  QUndoStack* undo = window_->document()->undoStack();
  const int steps = undo->count();
  const WoodParameters before = window_->document()->project().params;
  QSignalSpy failed(window_->workPath(), &WorkPath::reconstructFailed);
  QSignalSpy landed(window_->workPath(), &WorkPath::stageLanded);
  window_->workPath()->reconstructAction()->trigger();
  QVERIFY(window_->workPath()->isRunning());
  window_->workPath()->reconstructAction()->trigger();  // the same action stops it
  QCOMPARE(failed.count(), 1);
  QCOMPARE(failed.front().front().toString(), QStringLiteral("cancelled"));
  QVERIFY(window_->jobs()->waitForDone(kTimeoutMs));
  QCoreApplication::processEvents();
  QCOMPARE(landed.count(), 0);
  QCOMPARE(undo->count(), steps);
  QVERIFY(window_->document()->project().params == before);
}

// Which stages a later Reconstruct runs (issue 20 item 2): a stage runs when its result is stale or an
// earlier stage runs; the appearance only when asked for.
void TestFirstHour::planReconstructRerunsWhatDependsOnTheChange() {
  const auto plan = [](bool rings, bool field, bool wood, bool infer = true) {
    const ReconstructPlan p = planReconstruct({rings, field, wood}, infer);
    return QString("%1%2%3").arg(p.detect ? "R" : "-", p.fit ? "F" : "-", p.infer ? "A" : "-");
  };
  QCOMPARE(plan(false, false, false), QStringLiteral("RFA"));  // new photos: everything
  QCOMPARE(plan(false, true, true), QStringLiteral("RFA"));    // rings stale: what follows too
  QCOMPARE(plan(true, false, true), QStringLiteral("-FA"));    // a corrected ring: the field and the wood
  QCOMPARE(plan(true, true, false), QStringLiteral("--A"));    // a field edited by hand: the wood
  QCOMPARE(plan(true, true, true), QStringLiteral("---"));     // nothing changed
  QCOMPARE(plan(true, false, true, false), QStringLiteral("-F-"));
}

// After the walkthrough: the user deletes a wrong ring trace. Reconstruct then keeps the rings as they
// are (no detection, the deletion stays), refits the field and infers the wood again.
void TestFirstHour::aCorrectedRingRefitsWithoutDetectingAgain() {
  if (!window_->document()->hasPhotos()) QSKIP("needs the walkthrough's photos (../shared is absent)");
  Document* document = window_->document();
  QVERIFY(QTest::qWaitFor([&] { return !window_->isBusy(); }, kTimeoutMs));
  Annotations corrected = document->annotations();
  QVERIFY(corrected.traces.size() > 4);
  corrected.traces.erase(corrected.traces.begin());
  document->editAnnotations(corrected, QStringLiteral("Delete trace"));
  const std::size_t traces = document->annotations().traces.size();
  QUndoStack* undo = document->undoStack();
  const int steps = undo->count();
  QList<ReconstructStage> started;
  WorkPath* path = window_->workPath();
  QObject scope;  // the lambda captures this function's locals
  connect(path, &WorkPath::stageStarted, &scope, [&](ReconstructStage stage) { started << stage; });
  QSignalSpy done(path, &WorkPath::reconstructed);
  QSignalSpy failed(path, &WorkPath::reconstructFailed);
  path->reconstructAction()->trigger();
  QVERIFY(path->isRunning());
  QVERIFY(QTest::qWaitFor([&] { return done.count() + failed.count() > 0; }, kTimeoutMs));
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  const QList<ReconstructStage> rerun = {ReconstructStage::Field, ReconstructStage::Appearance};
  QCOMPARE(started, rerun);
  QCOMPARE(document->annotations().traces.size(), traces);  // the correction is kept
  QCOMPARE(undo->count(), steps + 2);
  QCOMPARE(undo->text(undo->count() - 2), QStringLiteral("Fit growth field"));
  QCOMPARE(undo->text(undo->count() - 1), QStringLiteral("Infer texture"));
  QVERIFY(window_->log()->text().contains(QStringLiteral("the rings are kept as they are")));
  // How sure the refitted field is: being estimated, as after any fit (or, on a very fast machine,
  // already known); the walkthrough has checked what it gives, so it is stopped here.
  QVERIFY(window_->rings()->isEstimatingUncertainty() || document->ringUncertainty());
  window_->rings()->cancelUncertainty();
  QVERIFY(window_->jobs()->waitForDone(kTimeoutMs));
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  qputenv("KERF_DEFAULT_LAYOUT", "1");
  TestFirstHour test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_first_hour.moc"
