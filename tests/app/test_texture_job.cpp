// Texture ▸ Infer Texture from Photos end to end on a small demo block: refused without a document,
// cancel leaves the document as it was, a run previews the faces live, applies the inferred detail as one
// undo step, and undo/redo restore and reapply it.
#include <QAction>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include "demo/demo_block.hpp"
#include "document.hpp"
#include "job_runner.hpp"
#include "log_panel.hpp"
#include "main_window.hpp"
#include "quick_texture_options.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 120000;
}  // namespace

class TestTextureJob : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void refusesWithoutDocument();
  void cancelLeavesDocument();
  void infersAsOneUndoStep();

 private:
  QTemporaryDir dir_;
  QString project_;
  std::unique_ptr<MainWindow> window_;
};

void TestTextureJob::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  DemoOptions options;
  options.facePixels = 128;
  options.samples = 1;
  project_ = QString::fromStdString(writeDemo(dir_.filePath("demo").toStdString(), options).project.string());
  window_ = std::make_unique<MainWindow>(RenderSettings{3.2f, 1});  // 128 px faces, like the photos
  window_->setAskBeforeDiscarding(false);
  window_->texture()->setTextureOptions(kerf::testing::quickTextureOptions());
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
}

void TestTextureJob::refusesWithoutDocument() {
  QSignalSpy failed(window_.get(), &MainWindow::textureJobFailed);
  window_->inferTextureAction()->trigger();
  QCOMPARE(failed.count(), 1);
  QVERIFY(window_->lastError().contains("needs photos of the faces"));
  QVERIFY(!window_->isBusy());

  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(project_);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
}

void TestTextureJob::cancelLeavesDocument() {
  Document* document = window_->document();
  const WoodParameters before = document->project().params;
  const int steps = document->undoStack()->count();
  QSignalSpy inferred(window_.get(), &MainWindow::textureInferred);
  QSignalSpy failed(window_.get(), &MainWindow::textureJobFailed);
  window_->inferTextureAction()->trigger();
  QVERIFY(window_->isBusy());
  window_->jobs()->cancelAll();
  QCOMPARE(failed.count(), 1);
  QVERIFY(window_->jobs()->waitForDone(kTimeoutMs));
  QTest::qWait(100);
  QCOMPARE(inferred.count(), 0);
  QCOMPARE(document->undoStack()->count(), steps);
  QVERIFY(document->project().params == before);
}

void TestTextureJob::infersAsOneUndoStep() {
  Document* document = window_->document();
  const WoodParameters before = document->project().params;
  const int steps = document->undoStack()->count();
  QSignalSpy inferred(window_.get(), &MainWindow::textureInferred);
  QSignalSpy failed(window_.get(), &MainWindow::textureJobFailed);
  QSignalSpy previewed(window_.get(), &MainWindow::texturePreviewed);
  window_->inferTextureAction()->trigger();
  QVERIFY(window_->isBusy());
  QTRY_VERIFY_WITH_TIMEOUT(inferred.count() + failed.count() > 0, kTimeoutMs);
  QVERIFY2(failed.isEmpty(), qPrintable(window_->lastError()));
  QVERIFY2(previewed.count() >= 1, qPrintable(QString("%1 previews").arg(previewed.count())));

  QCOMPARE(document->undoStack()->count(), steps + 1);
  QCOMPARE(document->undoStack()->undoText(), QStringLiteral("Infer texture"));
  const WoodParameters after = document->project().params;
  QVERIFY(after != before);
  QVERIFY(after.poreRadiusEarly != before.poreRadiusEarly || after.poreCellSize != before.poreCellSize ||
          after.raySpacing != before.raySpacing || after.fiberStrength != before.fiberStrength);
  QVERIFY(after.ringWidth == before.ringWidth);  // the growth field is not the texture's to change
  const QString log = window_->log()->text();
  for (const char* expected : {"end grain", "side grain", "style ", "loss on 6 crops", "Texture inferred"})
    QVERIFY2(log.contains(QLatin1String(expected)), expected);

  window_->undoAction()->trigger();
  QVERIFY(document->project().params == before);
  window_->redoAction()->trigger();
  QVERIFY(document->project().params == after);
}

QTEST_MAIN(TestTextureJob)
#include "test_texture_job.moc"
