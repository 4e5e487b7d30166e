// File > Export > Part… in the editor (issue 7): the dialog filled programmatically, its live fit line,
// the placed part in the 3D view while it is open, the export run as a background job, and the files.
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>

#include "demo_window.hpp"
#include "image_change.hpp"
#include "io/image.hpp"
#include "main_window.hpp"
#include "part_export_dialog.hpp"
#include "viewport3d.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 60000;

// A 16 x 10 x 24 mm box as OBJ (quads).
QString writeBox(const QString& path) {
  std::ofstream f(path.toStdString());
  for (int i = 0; i < 8; ++i)
    f << "v " << ((i & 1) ? 8 : -8) << ' ' << ((i & 2) ? 5 : -5) << ' ' << ((i & 4) ? 12 : -12) << '\n';
  f << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return path;
}
}  // namespace

class TestPartExportDialog : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
    QCoreApplication::setOrganizationName("KerfTestPartExport");  // never the user's settings
    window_ = kerf::testing::openDemoWindow(dir_.filePath("demo"), 48, {1400, 900}, kTimeoutMs);
    QVERIFY(window_);
  }

  void placeCheckFitAndExport() {
    Viewport3D* view = window_->viewport();
    view->setReducedResolutionDivisor(1);
    view->refineNow();
    const QImage before = view->grabFramebuffer();

    PartExportDialog* dialog = window_->exports()->showPartExportDialog();
    QVERIFY(dialog->isVisible());
    QVERIFY(!view->showsPart());
    QVERIFY(dialog->fitText().startsWith("Choose a mesh"));
    // No mesh yet: Export refuses and says why.
    dialog->accept();
    QVERIFY(dialog->isVisible());

    dialog->setMeshPath(writeBox(dir_.filePath("box.obj")));
    QVERIFY(dialog->meshLoaded());
    QVERIFY(view->showsPart());
    QVERIFY2(dialog->fitText().startsWith("The part fits in the block (at least 8.0 mm"),
             qPrintable(dialog->fitText()));

    // Pushed 14 mm towards +x and turned: sticks out at face E, said in the dialog.
    PartPlacement placement;
    placement.translationMm = {14, 0, 0};
    placement.centreInBlock = true;
    dialog->setPlacement(placement);
    QVERIFY(!dialog->fits());
    QVERIFY2(dialog->fitText().startsWith("The part sticks out of the block by 2.0 mm at face E (+x)"),
             qPrintable(dialog->fitText()));
    placement.translationMm = {2, -3, 1};
    placement.rotationDeg = {0, 30, 0};
    dialog->setPlacement(placement);
    QVERIFY2(dialog->fits(), qPrintable(dialog->fitText()));

    // The 3D view shows the placed part in the ghosted block.
    view->refineNow();
    const QImage shown = view->grabFramebuffer();
    QVERIFY(shown.save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/part_export_dialog_view.png")));
    QVERIFY(window_->grab().save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/part_export_dialog_window.png")));
    QVERIFY(dialog->grab().save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/part_export_dialog.png")));
    QVERIFY(testing::changedShare(before, shown) > 0.05);

    const QString out = dir_.filePath("part.obj");
    dialog->setPath(out);
    dialog->setTextureResolution(256);
    QSignalSpy finished(window_.get(), &MainWindow::exportFinished);
    dialog->accept();
    QVERIFY(!view->showsPart());  // closing the dialog takes the part out of the view
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
    QCOMPARE(finished.at(0).at(0).toString(), out);
    const QString message = finished.at(0).at(1).toString();
    QVERIFY2(message.contains("12 triangles in 6 charts, 256 px texture"), qPrintable(message));
    QVERIFY(QFile::exists(dir_.filePath("part.mtl")));
    const Image texture = readImage(dir_.filePath("part.png").toStdString());
    QCOMPARE(texture.width, 256);
    QFile obj(out);
    QVERIFY(obj.open(QIODevice::ReadOnly));
    QVERIFY(obj.readAll().contains("mtllib part.mtl"));
  }

  void glbWhenTheFormatIsChosen() {
    PartExportDialog* dialog = window_->exports()->showPartExportDialog();
    dialog->setMeshPath(writeBox(dir_.filePath("box2.obj")));
    dialog->setPath(dir_.filePath("part2.obj"));
    auto* format = dialog->findChild<QComboBox*>();
    QVERIFY(format);
    format->setCurrentIndex(1);  // glTF
    QCOMPARE(dialog->path(), dir_.filePath("part2.glb"));
    dialog->setTextureResolution(64);
    QSignalSpy finished(window_.get(), &MainWindow::exportFinished);
    dialog->accept();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
    QFile glb(dir_.filePath("part2.glb"));
    QVERIFY(glb.open(QIODevice::ReadOnly));
    QCOMPARE(glb.read(4), QByteArray("glTF"));
  }

  void cleanupTestCase() { window_.reset(); }

 private:
  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(TestPartExportDialog)
#include "test_part_export_dialog.moc"
