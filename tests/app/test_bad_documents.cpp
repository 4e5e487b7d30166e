// The editor and the catalogue of bad inputs (docs/reliability.md): opening each bad document shows an
// error that names the file, and leaves the open document exactly as it was (same project, same name,
// not modified), still usable.
#include <QFile>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "demo/demo_block.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "gpu/surface_format.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "main_window.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 60000;

void writeText(const QString& path, const QByteArray& bytes) {
  QFile file(path);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write(bytes);
}
}  // namespace

class TestBadDocuments : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void badDocumentLeavesTheOpenOneUnchanged_data();
  void badDocumentLeavesTheOpenOneUnchanged();
  void cleanupTestCase() { window_.reset(); }

 private:
  QMessageBox* visibleMessageBox() const {
    for (QMessageBox* box : window_->findChildren<QMessageBox*>())
      if (box->isVisible()) return box;
    return nullptr;
  }
  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestBadDocuments::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  DemoOptions options;
  options.facePixels = 32;
  options.samples = 1;
  const QString project =
      QString::fromStdString(writeDemo(dir_.filePath("demo").toStdString(), options).project.string());
  window_ = std::make_unique<MainWindow>(RenderSettings{0.8f, 1});
  window_->setAskBeforeDiscarding(false);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(project);
  QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kTimeoutMs);
}

void TestBadDocuments::badDocumentLeavesTheOpenOneUnchanged_data() {
  QTest::addColumn<QString>("path");
  QTest::addColumn<QString>("problem");
  const auto project = [&](const char* name, const QByteArray& text) {
    writeText(dir_.filePath(name), text);
    return dir_.filePath(name);
  };
  QTest::newRow("format of the wrong type")
      << project("format.kerf", R"({"format": 5, "version": 1})") << "not a Kerf project";
  QTest::newRow("future version") << project("future.kerf", R"({"format": "kerf-project", "version": 9})")
                                  << "written by a newer Kerf";
  QTest::newRow("infinite parameter")
      << project("inf.kerf",
                 R"({"format": "kerf-project", "version": 1, "parameters": {"growth.ring_width": 1e999}})")
      << "number overflow";
  QTest::newRow("truncated") << project("truncated.kerf", R"({"format": "kerf-project", "vers)")
                             << "is not valid JSON";
  // Issue 21: a list nested 100,000 deep overflowed the editor's stack; the shared reader refuses it.
  QTest::newRow("nested 100000 deep")
      << project("deep.kerf", R"({"format": "kerf-project", "version": 1, "block": {"size_mm": )" +
                                  QByteArray(100000, '[') + "1" + QByteArray(100000, ']') + "}}")
      << "nested deeper than 64 levels";
  QTest::newRow("duplicate key") << project("twice.kerf",
                                            R"({"format": "kerf-project", "version": 1, "version": 1})")
                                 << "the key \"version\" appears twice";
  QVERIFY(QDir(dir_.path()).mkpath("empty-sample"));
  QTest::newRow("empty sample folder") << dir_.filePath("empty-sample") << "holds no face photos";
  QVERIFY(QDir(dir_.path()).mkpath("odd-sample"));
  for (const char* face : {"A", "B", "C", "D", "E", "F"})
    writeImage(dir_.filePath(QStringLiteral("odd-sample/%1_col.png").arg(face)).toStdString(),
               Image(16, 16, 3));
  writeImage(dir_.filePath("odd-sample/B_col.png").toStdString(), Image(16, 24, 3));
  QTest::newRow("faces of different sizes") << dir_.filePath("odd-sample") << "B_col.png is 16 x 24 px";
}

void TestBadDocuments::badDocumentLeavesTheOpenOneUnchanged() {
  QFETCH(QString, path);
  QFETCH(QString, problem);
  const nlohmann::json before = projectToJson(window_->document()->project(), "/");
  const QString name = window_->documentName();

  QSignalSpy failed(window_.get(), &MainWindow::documentFailed);
  window_->openDocument(path);
  QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, kTimeoutMs);
  const QString error = window_->lastError();
  // The file at fault: the document itself, or the photo of a sample folder that is wrong.
  const QString named =
      problem.contains("_col.png") ? problem.section(' ', 0, 0) : QFileInfo(path).fileName();
  QVERIFY2(error.contains(named), qPrintable(error));
  QVERIFY2(error.contains(problem), qPrintable(error));
  QMessageBox* box = visibleMessageBox();
  QVERIFY(box);
  box->accept();
  QTRY_VERIFY_WITH_TIMEOUT(!visibleMessageBox(), kTimeoutMs);

  QVERIFY(!window_->isBusy());
  QCOMPARE(window_->documentName(), name);
  QVERIFY(!window_->isWindowModified());
  QVERIFY(projectToJson(window_->document()->project(), "/") == before);
  QVERIFY(window_->facesView()->hasFaces());
}

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("KerfTests"));
  qputenv("KERF_DEFAULT_LAYOUT", "1");
  TestBadDocuments test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_bad_documents.moc"
