// Killing Kerf (SIGKILL, as a crash or a power cut would) loses no work (issue 8):
// - during a growth-field fit: the project on disk is untouched, and the next start finds the autosave
//   copy with the unsaved edit and recovers it;
// - during saves: whenever the kill lands, the project file is a complete project, the last one or the
//   one before it (saves are atomic), never a truncated one;
// - during an export over an earlier export: the earlier file is untouched, and the partial temporary the
//   kill leaves is removed by the next export to the same file.
// The editor runs in a child process (crash_child.cpp) that is killed from here.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "autosave.hpp"
#include "demo/demo_block.hpp"
#include "document.hpp"
#include "export/volume_export.hpp"
#include "io/project.hpp"
#include "main_window.hpp"
#include "render/wood_model.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 120000;

// Starts the child and waits until it prints `line` (true) or ends (false).
bool startUntil(QProcess& child, const QStringList& arguments, const QByteArray& line) {
  child.setProgram(QStringLiteral(KERF_CRASH_CHILD));
  child.setArguments(arguments);
  child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
  child.start();
  if (!child.waitForStarted(kTimeoutMs)) return false;
  QByteArray seen;
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < kTimeoutMs) {
    if (child.canReadLine() || child.waitForReadyRead(200)) {
      while (child.canReadLine()) {
        seen = child.readLine().trimmed();
        if (seen.startsWith(line)) return true;
      }
    }
    if (child.state() == QProcess::NotRunning) return false;
  }
  return false;
}

void killNow(QProcess& child) {
  child.kill();  // SIGKILL: no handler runs, nothing is flushed or cleaned up
  child.waitForFinished(kTimeoutMs);
}
}  // namespace

class TestCrashRecovery : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void killedDuringAFitKeepsTheProjectAndRecoversTheEdit();
  void killedDuringSavesLeavesACompleteProject();
  void killedDuringAnExportKeepsTheEarlierFile();

 private:
  QTemporaryDir dir_;
  QString project_;
};

void TestCrashRecovery::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());  // the child inherits it
  DemoOptions options;
  options.facePixels = 128;
  options.samples = 1;
  project_ = QString::fromStdString(writeDemo(dir_.filePath("demo").toStdString(), options).project.string());
}

void TestCrashRecovery::killedDuringAFitKeepsTheProjectAndRecoversTheEdit() {
  QFile file(project_);
  QVERIFY(file.open(QIODevice::ReadOnly));
  const QByteArray before = file.readAll();
  file.close();

  QProcess child;
  QVERIFY2(startUntil(child, {"fit", project_}, "fitting"), "the child never started its fit");
  QTest::qWait(QRandomGenerator::global()->bounded(50, 400));  // somewhere inside the fit
  killNow(child);
  QCOMPARE(child.exitStatus(), QProcess::CrashExit);
  QVERIFY2(!child.readAllStandardOutput().contains("fitted"), "the fit ended before the kill");

  QVERIFY(file.open(QIODevice::ReadOnly));
  QCOMPARE(file.readAll(), before);  // the fit never touched the project file
  file.close();

  // The next start finds the copy and recovers the unsaved edit, attached to the original file.
  MainWindow next(RenderSettings{1.6f, 1});
  next.setAskBeforeDiscarding(false);
  const QStringList leftovers = next.autosave()->leftovers();
  QCOMPARE(leftovers.size(), 1);
  QSignalSpy ready(&next, &MainWindow::documentReady);
  next.recover(leftovers.front());
  QCOMPARE(next.document()->project().params.ringWidth, 5.5f);
  QVERIFY(next.document()->isModified());
  QCOMPARE(next.document()->filePath(), QFileInfo(project_).absoluteFilePath());
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
  QVERIFY(next.autosave()->leftovers().isEmpty());
}

void TestCrashRecovery::killedDuringSavesLeavesACompleteProject() {
  for (int round = 0; round < 12; ++round) {
    QProcess child;
    QVERIFY2(startUntil(child, {"save", project_}, "saved 3"), "the child never saved");
    QTest::qWait(QRandomGenerator::global()->bounded(0, 60));  // lands anywhere in a later save
    killNow(child);
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);
    if (round == 0) qInfo("project file: %lld bytes", QFileInfo(project_).size());
    try {
      const Project project = loadProject(project_.toStdString());
      const float ring = project.params.ringWidth;
      QVERIFY2(ring == 2.0f || ring == 3.0f, qPrintable(QString("ring width %1").arg(ring)));
    } catch (const std::exception& e) {
      QFAIL(qPrintable(QString("round %1: the project no longer loads: %2").arg(round).arg(e.what())));
    }
  }
}

void TestCrashRecovery::killedDuringAnExportKeepsTheEarlierFile() {
  const QString folder = dir_.filePath("exports");
  QVERIFY(QDir().mkpath(folder));
  const QString out = folder + "/block.nrrd";
  const WoodModel model(loadProject(project_.toStdString()));
  exportVolume(model, VolumeQuantity::Color, 16, out.toStdString());  // the earlier export
  QFile file(out);
  QVERIFY(file.open(QIODevice::ReadOnly));
  const QByteArray earlier = file.readAll();
  file.close();

  QProcess child;
  QVERIFY2(startUntil(child, {"export", project_, out}, "exporting"), "the child never started its export");
  QTest::qWait(QRandomGenerator::global()->bounded(100, 600));  // 32 M voxels take seconds
  killNow(child);
  QCOMPARE(child.exitStatus(), QProcess::CrashExit);
  QVERIFY2(!child.readAllStandardOutput().contains("exported"), "the export ended before the kill");
  QVERIFY(file.open(QIODevice::ReadOnly));
  QCOMPARE(file.readAll(), earlier);
  file.close();

  // What the kill left: the partial hidden temporary, if the writer had got that far.
  const QStringList others =
      QDir(folder).entryList(QDir::Files | QDir::Hidden).filter(QRegularExpression("^\\."));
  qInfo("left by the kill: %s", others.isEmpty() ? "nothing" : qPrintable(others.join(", ")));
  QVERIFY(others.size() <= 1);
  exportVolume(model, VolumeQuantity::Color, 8, out.toStdString());  // the next export of that file
  QCOMPARE(QDir(folder).entryList(QDir::Files | QDir::Hidden), QStringList{"block.nrrd"});
}

QTEST_MAIN(TestCrashRecovery)
#include "test_crash_recovery.moc"
