// File > Import Photos: the dialog driven as a user would (photos in, corners dragged, face, turn and
// white balance chosen, OK), then the background write and the one undo step that puts the faces and
// the block's size into the document.
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <cmath>

#include "corner_picker_view.hpp"
#include "demo/demo_block.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "job_runner.hpp"
#include "photo_import.hpp"
#include "photo_import_dialog.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

constexpr int kTimeoutMs = 30000;

// A face image in its own orientation: rings, and a red marker over the top-left quarter.
QImage faceImage(int width, int height) {
  QImage image(width, height, QImage::Format_RGB32);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double r = std::hypot(x + 0.5 + 0.3 * width, y + 0.5 - 1.4 * height);
      const double ring = 0.5 + 0.5 * std::sin(r * 0.5);
      QColor c = QColor::fromRgbF(0.45 + 0.35 * ring, 0.32 + 0.25 * ring, 0.18 + 0.12 * ring);
      if (x < width / 4 && y < height / 4) c = QColor(230, 30, 30);
      image.setPixel(x, y, c.rgb());
    }
  return image;
}

// `picture` photographed in perspective: its corners land on `quad` of a w x h photo of grey paper,
// then every pixel is multiplied by `cast` (the colour of the light).
QImage photograph(const QImage& picture, const QPolygonF& quad, QSize size,
                  QColor paper = QColor(205, 205, 205), std::array<double, 3> cast = {1, 1, 1}) {
  QImage photo(size, QImage::Format_RGB32);
  photo.fill(paper);
  QPainter painter(&photo);
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.setRenderHint(QPainter::Antialiasing);
  QTransform transform;
  const QRectF r(picture.rect());
  if (!QTransform::quadToQuad(QPolygonF({r.topLeft(), r.topRight(), r.bottomRight(), r.bottomLeft()}), quad,
                              transform))
    qFatal("quadToQuad failed");
  painter.setTransform(transform);
  painter.drawImage(QRectF(picture.rect()), picture);
  painter.end();
  for (int y = 0; y < photo.height(); ++y)
    for (int x = 0; x < photo.width(); ++x) {
      const QRgb p = photo.pixel(x, y);
      photo.setPixel(x, y,
                     qRgb(std::min(255, static_cast<int>(qRed(p) * cast[0])),
                          std::min(255, static_cast<int>(qGreen(p) * cast[1])),
                          std::min(255, static_cast<int>(qBlue(p) * cast[2]))));
    }
  return photo;
}

std::array<glm::vec2, 4> cornersOf(const QPolygonF& quad) {
  return {glm::vec2(quad[0].x(), quad[0].y()), glm::vec2(quad[1].x(), quad[1].y()),
          glm::vec2(quad[2].x(), quad[2].y()), glm::vec2(quad[3].x(), quad[3].y())};
}

bool isRed(QRgb p) {
  return qRed(p) > 170 && qGreen(p) < 90 && qBlue(p) < 90;
}

}  // namespace

class TestPhotoImport : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void importsPhotosAsOneUndoStep();

 private:
  QTemporaryDir dir_;
  QString photoA_, photoE_, broken_;
  // Face A of a 60 x 40 x 30 mm block (60 x 40 mm) and face E (30 x 40 mm), where they lie on the photos.
  const QPolygonF quadA_{
      {QPointF(152.4, 96.8), QPointF(731.5, 141.2), QPointF(702.3, 548.9), QPointF(118.6, 497.0)}};
  const QPolygonF quadE_{
      {QPointF(210.0, 160.5), QPointF(655.2, 120.3), QPointF(690.8, 420.7), QPointF(240.1, 455.6)}};
};

void TestPhotoImport::initTestCase() {
  QVERIFY(dir_.isValid());
  // A: straight, named for its face. E: named like a camera file, photographed lying on its side (the
  // picture is the face turned a quarter anticlockwise, so it needs a quarter turn clockwise), under a
  // warm light.
  photoA_ = dir_.filePath("A_front.png");
  QVERIFY(photograph(faceImage(240, 160), quadA_, {900, 650}).save(photoA_));
  const QImage faceE = faceImage(120, 160).transformed(QTransform().rotate(-90));
  photoE_ = dir_.filePath("IMG_2041.png");
  QVERIFY(photograph(faceE, quadE_, {900, 650}, QColor(205, 205, 205), {1.2, 1.0, 0.7}).save(photoE_));
  broken_ = dir_.filePath("broken.png");
  QFile file(broken_);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write("not a picture");
}

void TestPhotoImport::importsPhotosAsOneUndoStep() {
  Document document;
  document.reset(demoProject(), {}, "demo", {});
  const glm::vec3 sizeBefore = document.project().block.size();
  JobRunner jobs;

  PhotoImportDialog dialog(document.project().block, document.photos());
  dialog.setAskBeforeReplacing(false);
  dialog.show();
  QVERIFY(QTest::qWaitForWindowExposed(&dialog));
  QSignalSpy loaded(&dialog, &PhotoImportDialog::photosLoaded);
  dialog.addPhotos({photoA_, photoE_, broken_});
  QTRY_VERIFY_WITH_TIMEOUT(!dialog.isLoading(), kTimeoutMs);
  QVERIFY(loaded.count() >= 1);

  // The unreadable file is dropped with a message; the others are guessed: A from its name, the camera
  // file gets the first free face.
  QCOMPARE(dialog.photoCount(), 2);
  QVERIFY2(dialog.lastError().contains("broken.png"), qPrintable(dialog.lastError()));
  QCOMPARE(dialog.face(0), std::optional<FaceId>(FaceId::A));
  QCOMPARE(dialog.face(1), std::optional<FaceId>(FaceId::B));
  QCOMPARE(dialog.photoSize(0), QSize(900, 650));
  // Default corners: a face-shaped outline inside the photo, usable as it is.
  validateCorners(dialog.setup(0).corners, {900, 650});
  QCOMPARE(dialog.outputFolder(), dir_.filePath("kerf-faces"));

  // The block: a cuboid, written at 4 px/mm, into a folder of our own.
  dialog.setBlockSize({60, 40, 30});
  dialog.setPxPerMm(4);
  const QString folder = dir_.filePath("faces");
  dialog.setOutputFolder(folder);

  // Drag handle 1 of photo A with the mouse, as a user would: it follows the pointer.
  dialog.setCurrentPhoto(0);
  CornerPickerView* picker = dialog.cornerPicker();
  const QPoint from =
      picker->photoToWidget(QPointF(dialog.setup(0).corners[0].x, dialog.setup(0).corners[0].y)).toPoint();
  const QPoint to = picker->photoToWidget(quadA_[0]).toPoint();
  QTest::mousePress(picker, Qt::LeftButton, {}, from);
  QTest::mouseMove(picker, (from + to) / 2);
  QVERIFY(!picker->loupeRect().isNull());  // the loupe shows the corner close up while dragging
  QTest::mouseMove(picker, to);
  QTest::mouseRelease(picker, Qt::LeftButton, {}, to);
  const QPointF dropped = picker->widgetToPhoto(to);
  QVERIFY(std::abs(dialog.setup(0).corners[0].x - dropped.x()) < 1.5);
  QVERIFY(std::abs(dialog.setup(0).corners[0].y - dropped.y()) < 1.5);
  // Then place all four exactly (the mouse is only as precise as the screen).
  dialog.setCorners(0, cornersOf(quadA_));

  // Photo E: its face, a quarter turn, automatic white balance.
  dialog.setCurrentPhoto(1);
  dialog.setFace(1, FaceId::E);
  dialog.setCorners(1, cornersOf(quadE_));
  dialog.setRotation(1, 90);
  dialog.setWhiteBalance(1, WhiteBalanceMode::Auto);
  const glm::vec3 gains = dialog.setup(1).whiteBalance;
  QVERIFY2(gains.x < 0.95f * gains.y && gains.z > 1.2f * gains.y, "auto white balance undoes the warm light");

  // The live preview: both faces in the cross, at the faces' proportions, the marker top-left.
  QSignalSpy previewed(&dialog, &PhotoImportDialog::previewUpdated);
  QTRY_VERIFY_WITH_TIMEOUT(previewed.count() > 0, kTimeoutMs);
  const QImage previewA = dialog.previewFaces()[faceIndex(FaceId::A)];
  const QImage previewE = dialog.previewFaces()[faceIndex(FaceId::E)];
  QVERIFY(!previewA.isNull() && !previewE.isNull());
  QVERIFY(std::abs(previewA.width() / double(previewA.height()) - 60.0 / 40.0) < 0.02);
  QVERIFY(std::abs(previewE.width() / double(previewE.height()) - 30.0 / 40.0) < 0.02);
  QVERIFY(isRed(previewA.pixel(previewA.width() / 10, previewA.height() / 10)));
  QVERIFY(isRed(previewE.pixel(previewE.width() / 10, previewE.height() / 10)));
  QVERIFY(!isRed(previewE.pixel(previewE.width() * 9 / 10, previewE.height() / 10)));
  QVERIFY(dialog.problems().isEmpty());

  // Screenshot for review, with the loupe on handle 2 of photo E.
  const QPoint handle =
      picker->photoToWidget(QPointF(dialog.setup(1).corners[1].x, dialog.setup(1).corners[1].y)).toPoint();
  QTest::mouseMove(picker, handle);
  QTRY_VERIFY_WITH_TIMEOUT(!picker->loupeRect().isNull(), kTimeoutMs);
  const QImage shot = dialog.grab().toImage();
  QVERIFY(shot.save(QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/photo_import_dialog.png")));

  // OK refuses what cannot be imported, and stays open saying why.
  dialog.setFace(1, FaceId::A);
  dialog.accept();
  QVERIFY(dialog.isVisible());
  QVERIFY2(dialog.lastError().contains("both assigned to face A"), qPrintable(dialog.lastError()));
  dialog.setFace(1, FaceId::E);
  const auto goodE = dialog.setup(1).corners;
  dialog.setCorners(1, {goodE[0], goodE[1], goodE[3], goodE[2]});
  QVERIFY(!dialog.problems().isEmpty());  // the preview says so at once
  dialog.accept();
  QVERIFY(dialog.isVisible());
  QVERIFY2(dialog.lastError().contains("convex"), qPrintable(dialog.lastError()));
  dialog.setCorners(1, goodE);
  QVERIFY(document.undoStack()->count() == 0);
  for (QMessageBox* box : dialog.findChildren<QMessageBox*>()) box->close();  // the refusals' messages

  // OK.
  auto* buttons = dialog.findChild<QDialogButtonBox*>();
  QVERIFY(buttons);
  QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
  QCOMPARE(dialog.result(), int(QDialog::Accepted));
  QVERIFY(!dialog.isVisible());

  // The full-size faces are written in the background, then applied as one undo step.
  bool done = false;
  const PhotoImportPlan plan = dialog.plan();
  QCOMPARE(plan.faceCount(), 2);
  const int job = startPhotoImport(jobs, document, plan, [&done] { done = true; });
  QVERIFY(jobs.isRunning(job));
  QTRY_VERIFY_WITH_TIMEOUT(done, kTimeoutMs);

  QCOMPARE(document.project().block.size(), glm::vec3(60, 40, 30));
  QCOMPARE(document.undoStack()->count(), 1);
  QCOMPARE(document.undoStack()->undoText(), QString("Import photos of face A, E"));
  const QString fileA = QDir(folder).filePath("A_col.png"), fileE = QDir(folder).filePath("E_col.png");
  QCOMPARE(QString::fromStdString(document.project().facePhotos[faceIndex(FaceId::A)].string()), fileA);
  QCOMPARE(QString::fromStdString(document.project().facePhotos[faceIndex(FaceId::E)].string()), fileE);
  QVERIFY(document.project().facePhotos[faceIndex(FaceId::B)].empty());
  const QImage writtenA(fileA), writtenE(fileE);
  QCOMPARE(writtenA.size(), QSize(240, 160));  // 60 x 40 mm at 4 px/mm
  QCOMPARE(writtenE.size(), QSize(120, 160));  // 30 x 40 mm
  QCOMPARE(document.photos()[faceIndex(FaceId::A)].size(), QSize(240, 160));
  // Corners and turn were honoured at full size: the marker is top-left, the rest is wood.
  QVERIFY(isRed(writtenA.pixel(20, 15)));
  QVERIFY(!isRed(writtenA.pixel(200, 120)));
  QVERIFY(isRed(writtenE.pixel(12, 15)));
  QVERIFY(!isRed(writtenE.pixel(100, 15)));
  QVERIFY(!isRed(writtenE.pixel(12, 140)));
  // White balanced: the wood of E is as warm as A's (same wood under a neutral light), not orange.
  const QColor woodA(writtenA.pixel(200, 120)), woodE(writtenE.pixel(100, 140));
  const double ratioA = woodA.blueF() / woodA.greenF(), ratioE = woodE.blueF() / woodE.greenF();
  QVERIFY2(std::abs(ratioE - ratioA) < 0.08,
           qPrintable(QString("blue/green A %1 E %2").arg(ratioA).arg(ratioE)));

  // One undo restores the block and the photos; redo brings them back.
  document.undoStack()->undo();
  QCOMPARE(document.project().block.size(), sizeBefore);
  QVERIFY(document.project().facePhotos[faceIndex(FaceId::A)].empty());
  QVERIFY(document.photos()[faceIndex(FaceId::A)].isNull());
  QVERIFY(!document.hasPhotos());
  document.undoStack()->redo();
  QCOMPARE(document.project().block.size(), glm::vec3(60, 40, 30));
  QCOMPARE(document.photos()[faceIndex(FaceId::E)].size(), QSize(120, 160));
}

QTEST_MAIN(TestPhotoImport)
#include "test_photo_import.moc"
