// File > Export in the editor: the dialogs filled programmatically (no modal loop), the export run as a
// background job, and the files it wrote read back (scale, layers, depth index); a failing export reports.
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "demo_window.hpp"
#include "document.hpp"
#include "export/image_export.hpp"
#include "export_dialog.hpp"
#include "io/image.hpp"
#include "job_runner.hpp"
#include "main_window.hpp"
#include "render/renderers.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 60000;
}  // namespace

class TestExportDialog : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void faceImageThroughTheDialog();
  void dialogRefusesAMismatchedExtension();
  void depthStackThroughTheDialog();
  void tooLargeAnImageIsRefusedAndSaidAtOnce();
  void failedExportIsReported();

 private:
  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestExportDialog::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  QCoreApplication::setOrganizationName("KerfTestExport");  // never the user's settings
  window_ = kerf::testing::openDemoWindow(dir_.filePath("demo"), 48, {}, kTimeoutMs);
  QVERIFY(window_);
  for (int k = 0; k < 4; ++k) QVERIFY(window_->exportAction(static_cast<ExportDialog::Kind>(k)));
}

void TestExportDialog::faceImageThroughTheDialog() {
  ExportDialog* dialog = window_->exports()->showExportDialog(ExportDialog::Kind::FaceImage);
  QVERIFY(dialog->isVisible());
  const QString path = dir_.filePath("face_A.exr");
  dialog->setPath(path);
  dialog->setPxPerMm(2.0);
  auto* format = dialog->findChild<QComboBox*>();  // the first combo box: the format
  QVERIFY(format);
  QCOMPARE(format->currentText().left(8), QStringLiteral("OpenEXR "));  // follows the path's extension
  QSignalSpy finished(window_.get(), &MainWindow::exportFinished);
  dialog->accept();
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
  QCOMPARE(finished.at(0).at(0).toString(), path);
  QVERIFY(finished.at(0).at(1).toString().contains("80 x 80 px"));

  const ExportedImageInfo info = readExportedImageInfo(path.toStdString());
  QCOMPARE(info.width, 80);
  QCOMPARE(info.channels, 5);  // R, G, B, growth, rings
  QVERIFY(info.channelNames.find("growth") != std::string::npos);
  QVERIFY(std::abs(info.dotsPerInch - 50.8f) < 0.01f);
  QVERIFY(std::abs(info.mmPerPixel - 0.5f) < 1e-6f);
  // The colour is the renderer's face A (EXR holds it linear: compare one bright and one dark value loosely).
  const Image written = readImage(path.toStdString());
  const Image reference = renderFace(*window_->document()->model(), FaceId::A, {80, 80}, 2);
  const float srgb = reference.pixel(40, 40)[0];
  const float linear = srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f);
  QVERIFY2(std::abs(written.pixel(40, 40)[0] - linear) < 2e-3f,
           qPrintable(QString::number(written.pixel(40, 40)[0])));
}

void TestExportDialog::dialogRefusesAMismatchedExtension() {
  ExportDialog* dialog = window_->exports()->showExportDialog(ExportDialog::Kind::CutImage);
  dialog->setPath(dir_.filePath("cut.nrrd"));  // a volume extension for an image
  dialog->accept();
  QVERIFY(dialog->isVisible());
  QCOMPARE(dialog->result(), int(QDialog::Rejected));
  dialog->setPath(dir_.filePath("no-extension"));
  dialog->accept();
  QVERIFY(dialog->isVisible());
  dialog->reject();
  QVERIFY(window_->jobs()->runningJobs().isEmpty());
}

void TestExportDialog::depthStackThroughTheDialog() {
  ExportDialog* dialog = window_->exports()->showExportDialog(ExportDialog::Kind::DepthStack);
  const QString folder = dir_.filePath("stack");
  dialog->setPath(folder);
  dialog->setPxPerMm(1.0);
  QCOMPARE(dialog->request().depthStack->depthMm, 5.0f);  // the dialog's defaults: step 1 mm, depth 5 mm
  QSignalSpy finished(window_.get(), &MainWindow::exportFinished);
  dialog->accept();
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
  for (int i = 0; i <= 5; ++i)
    QVERIFY(QFile::exists(QDir(folder).filePath(QString("A_%1.png").arg(i, 3, 10, QChar('0')))));
  QFile csv(QDir(folder).filePath("depths.csv"));
  QVERIFY(csv.open(QIODevice::ReadOnly));
  QCOMPARE(QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts).size(), 7);  // header + 6 depths
}

void TestExportDialog::tooLargeAnImageIsRefusedAndSaidAtOnce() {
  ExportDialog* dialog = window_->exports()->showExportDialog(ExportDialog::Kind::FaceImage);
  dialog->setPath(dir_.filePath("huge_A.tif"));
  dialog->setPxPerMm(10.0);
  QVERIFY2(dialog->sizeNote().startsWith("400 × 400 px"), qPrintable(dialog->sizeNote()));
  dialog->setPxPerMm(400.0);  // 16000 x 16000 px: over the 120 megapixels Kerf makes
  QVERIFY2(dialog->sizeNote().contains("would be 16000 x 16000 px") &&
               dialog->sizeNote().contains("use at most 273.86 px/mm"),
           qPrintable(dialog->sizeNote()));
  QTest::qWait(50);  // the layout makes room for the wrapped note
  QVERIFY(dialog->grab().save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/export_dialog_too_large.png")));
  QSignalSpy failed(window_.get(), &MainWindow::exportFailed);
  dialog->accept();  // the export refuses it at once, before taking the memory
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kTimeoutMs);
  QVERIFY2(failed.at(0).at(0).toString().contains("Kerf makes images of up to 120 megapixels"),
           qPrintable(failed.at(0).at(0).toString()));
  QVERIFY(!QFile::exists(dir_.filePath("huge_A.tif")));
}

void TestExportDialog::failedExportIsReported() {
  ExportRequest request;
  request.out = dir_.filePath("missing-folder/growth.vdb").toStdString();
  request.resolution = 8;
  QSignalSpy failed(window_.get(), &MainWindow::exportFailed);
  window_->exports()->startExport(request);
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kTimeoutMs);
  QVERIFY2(failed.at(0).at(0).toString().contains("does not exist"),
           qPrintable(failed.at(0).at(0).toString()));
  QVERIFY(window_->lastError().contains("does not exist"));  // shown in a message box and the log
  QVERIFY(!QFile::exists(dir_.filePath("missing-folder")));
}

QTEST_MAIN(TestExportDialog)
#include "test_export_dialog.moc"
