// FacesView's compare displays on synthetic faces of flat, known colours: Split shows the photo left of
// the line and the model right of it, the line follows the mouse; photo and model meet at the same face
// position whatever their resolutions; Difference is black where photo and model agree and coloured
// where they part (orange lighter, blue darker); a face without a photo shows the model. Also prints
// how long the heat maps of six 1024 px faces take (why they are computed off the GUI thread).
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>
#include <memory>

#include "demo/demo_block.hpp"
#include "face_difference.hpp"
#include "faces_view.hpp"

using namespace kerf;

namespace {

const QColor kPhoto(200, 140, 80), kModel(60, 90, 160);
constexpr int kTimeoutMs = 30000;  // the heat maps come from the background pool

QImage flat(QSize size, QColor colour) {
  QImage image(size, QImage::Format_RGB32);
  image.fill(colour);
  return image;
}

// Top half `top`, bottom half `bottom`: a horizontal edge to check registration with.
QImage halves(QSize size, QColor top, QColor bottom) {
  QImage image = flat(size, bottom);
  for (int y = 0; y < size.height() / 2; ++y)
    for (int x = 0; x < size.width(); ++x) image.setPixelColor(x, y, top);
  return image;
}

// Left half `left`, right half `right`.
QImage sides(QSize size, QColor left, QColor right) {
  QImage image = flat(size, right);
  for (int y = 0; y < size.height(); ++y)
    for (int x = 0; x < size.width() / 2; ++x) image.setPixelColor(x, y, left);
  return image;
}

bool near(QColor a, QColor b, int tolerance = 2) {
  return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
         std::abs(a.blue() - b.blue()) <= tolerance;
}

}  // namespace

class TestFacesCompare : public QObject {
  Q_OBJECT

 private slots:
  void init();
  void splitShowsPhotoLeftAndModelRight();
  void splitLineFollowsTheMouse();
  void photoAndModelMeetAtTheSameFacePosition();
  void differenceIsBlackWherePhotoAndModelAgree();
  void differenceColoursSayLighterOrDarker();
  void faceWithoutPhotoShowsTheModel();
  void differenceTiming();
  void cleanup() { view_.reset(); }

 private:
  QImage shot() { return view_->grab().toImage().convertToFormat(QImage::Format_RGB32); }
  // A point of face `face` at fractions (u, v) of its width and height, in widget pixels.
  QPoint at(FaceId face, double u, double v) const {
    const QRectF r = view_->faceRect(face);
    return QPointF(r.left() + u * r.width(), r.top() + v * r.height()).toPoint();
  }
  // Photos of kPhoto (none on F) at 120 x 90 px, the model of kModel at 40 x 30 px: different sizes on
  // purpose, the view registers them by face position.
  void setFlatFaces() {
    std::array<QImage, 6> photos, models;
    for (FaceId face : kAllFaces) {
      if (face != FaceId::F) photos[faceIndex(face)] = flat({120, 90}, kPhoto);
      models[faceIndex(face)] = flat({40, 30}, kModel);
    }
    view_->setPhotos(photos);
    view_->setRenderings(models);
  }

  std::unique_ptr<FacesView> view_;
};

void TestFacesCompare::init() {
  view_ = std::make_unique<FacesView>();
  view_->resize(960, 720);
  view_->setBlock(demoProject().block);
  view_->show();
  QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
}

void TestFacesCompare::splitShowsPhotoLeftAndModelRight() {
  setFlatFaces();
  view_->setDisplay(FaceDisplay::Split);
  QSignalSpy moved(view_.get(), &FacesView::splitPositionChanged);
  view_->setSplitPosition(0.3);
  QCOMPARE(moved.count(), 1);
  QImage image = shot();
  for (FaceId face : {FaceId::A, FaceId::B, FaceId::C, FaceId::D, FaceId::E}) {
    // At 60 % of the height: below the letter, above the side tags, off the grip.
    QVERIFY2(near(image.pixelColor(at(face, 0.15, 0.6)), kPhoto), qPrintable(QString(faceLetter(face))));
    QVERIFY2(near(image.pixelColor(at(face, 0.45, 0.6)), kModel), qPrintable(QString(faceLetter(face))));
    QVERIFY(near(image.pixelColor(at(face, 0.9, 0.6)), kModel));
  }
  view_->setSplitPosition(0.7);
  image = shot();
  QVERIFY(near(image.pixelColor(at(FaceId::A, 0.45, 0.6)), kPhoto));
  QVERIFY(near(image.pixelColor(at(FaceId::A, 0.9, 0.6)), kModel));
  // The ends: only the model, only the photo.
  view_->setSplitPosition(0.0);
  QVERIFY(near(shot().pixelColor(at(FaceId::A, 0.15, 0.6)), kModel));
  view_->setSplitPosition(1.0);
  QVERIFY(near(shot().pixelColor(at(FaceId::A, 0.9, 0.6)), kPhoto));
  view_->setSplitPosition(2.0);  // clamped
  QCOMPARE(view_->splitPosition(), 1.0);
}

void TestFacesCompare::splitLineFollowsTheMouse() {
  setFlatFaces();
  view_->setDisplay(FaceDisplay::Split);
  view_->setSplitPosition(0.5);
  const QRectF a = view_->faceRect(FaceId::A);
  QTest::mousePress(view_.get(), Qt::LeftButton, {}, at(FaceId::A, 0.5, 0.3));
  QTest::mouseMove(view_.get(), at(FaceId::A, 0.25, 0.3));
  QTest::mouseRelease(view_.get(), Qt::LeftButton, {}, at(FaceId::A, 0.25, 0.3));
  QVERIFY2(std::abs(view_->splitPosition() - 0.25) <= 1.5 / a.width(),
           qPrintable(QString::number(view_->splitPosition())));
  // Every face follows, and the pixels with it.
  const QImage image = shot();
  QVERIFY(near(image.pixelColor(at(FaceId::E, 0.15, 0.6)), kPhoto));
  QVERIFY(near(image.pixelColor(at(FaceId::E, 0.35, 0.6)), kModel));
  // A press away from the line does not take it.
  QTest::mousePress(view_.get(), Qt::LeftButton, {}, at(FaceId::A, 0.8, 0.3));
  QTest::mouseMove(view_.get(), at(FaceId::A, 0.9, 0.3));
  QTest::mouseRelease(view_.get(), Qt::LeftButton, {}, at(FaceId::A, 0.9, 0.3));
  QVERIFY(std::abs(view_->splitPosition() - 0.25) <= 1.5 / a.width());
}

void TestFacesCompare::photoAndModelMeetAtTheSameFacePosition() {
  // Photo and model share an edge half-way down the face, at different resolutions: left and right of
  // the line the edge is on the same screen row.
  const QColor top(30, 30, 30), bottom(230, 230, 230);
  std::array<QImage, 6> photos, models;
  for (FaceId face : kAllFaces) {
    photos[faceIndex(face)] = halves({200, 160}, top, bottom);
    models[faceIndex(face)] = halves({50, 40}, top, bottom);
  }
  view_->setPhotos(photos);
  view_->setRenderings(models);
  view_->setDisplay(FaceDisplay::Split);
  view_->setSplitPosition(0.5);
  const QImage image = shot();
  const auto edgeRow = [&](int x, const QRectF& r) {
    for (int y = static_cast<int>(r.top() + 0.3 * r.height()); y < r.top() + 0.7 * r.height(); ++y)
      if (qGray(image.pixel(x, y)) > 130) return y;
    return -1;
  };
  for (FaceId face : kAllFaces) {
    const QRectF r = view_->faceRect(face);
    const int photoRow = edgeRow(at(face, 0.3, 0).x(), r), modelRow = edgeRow(at(face, 0.7, 0).x(), r);
    QVERIFY(photoRow > 0);
    QVERIFY2(std::abs(photoRow - modelRow) <= 1,
             qPrintable(QStringLiteral("face %1: photo edge at row %2, model edge at %3")
                            .arg(faceLetter(face))
                            .arg(photoRow)
                            .arg(modelRow)));
  }
  // And the heat map of the same pair is black away from the edge (the resampled model's edge is soft).
  const QImage map = differenceHeatMap(photos[0], models[0]);
  QCOMPARE(map.size(), photos[0].size());
  QCOMPARE(map.pixelColor(100, 20), QColor(0, 0, 0));
  QCOMPARE(map.pixelColor(100, 140), QColor(0, 0, 0));
}

void TestFacesCompare::differenceIsBlackWherePhotoAndModelAgree() {
  // The model matches the photo on the left half of every face and is lighter on the right half.
  const QColor lighter(240, 180, 120);
  std::array<QImage, 6> photos, models;
  for (FaceId face : kAllFaces) {
    photos[faceIndex(face)] = flat({80, 80}, kPhoto);
    models[faceIndex(face)] = sides({80, 80}, kPhoto, lighter);
  }
  view_->setPhotos(photos);
  view_->setRenderings(models);
  view_->setDisplay(FaceDisplay::Difference);
  QTRY_VERIFY_WITH_TIMEOUT(view_->differenceUpToDate(), kTimeoutMs);
  const QImage map = view_->differenceMaps()[0];
  QCOMPARE(map.size(), QSize(80, 80));
  QCOMPARE(map.pixelColor(20, 40), QColor(0, 0, 0));
  QVERIFY(map.pixelColor(60, 40) != QColor(0, 0, 0));
  const QImage image = shot();
  for (FaceId face : kAllFaces) {
    QCOMPARE(image.pixelColor(at(face, 0.25, 0.6)), QColor(0, 0, 0));
    const QColor differs = image.pixelColor(at(face, 0.75, 0.6));
    QVERIFY2(differs.red() > 150 && differs.red() > differs.blue(), qPrintable(differs.name()));  // orange
  }
  // A new model: the maps follow (the old ones stay shown until the new ones come).
  for (FaceId face : kAllFaces) models[faceIndex(face)] = photos[faceIndex(face)];
  view_->setRenderings(models);
  QVERIFY(!view_->differenceUpToDate());
  QTRY_VERIFY_WITH_TIMEOUT(view_->differenceUpToDate(), kTimeoutMs);
  QCOMPARE(shot().pixelColor(at(FaceId::A, 0.75, 0.6)), QColor(0, 0, 0));
}

void TestFacesCompare::differenceColoursSayLighterOrDarker() {
  QCOMPARE(QColor(differenceColour(0, 0)), QColor(0, 0, 0));
  const QColor lighter(differenceColour(kDifferenceFullScale, kDifferenceFullScale));
  const QColor darker(differenceColour(kDifferenceFullScale, -kDifferenceFullScale));
  const QColor hue(differenceColour(kDifferenceFullScale, 0));
  QVERIFY(lighter.red() > lighter.blue() + 100);
  QVERIFY(darker.blue() > darker.red() + 100);
  QCOMPARE(hue, QColor(255, 255, 255));
  // Larger differences are brighter, up to the full scale.
  QVERIFY(QColor(differenceColour(10, 10)).red() < QColor(differenceColour(40, 40)).red());
  QCOMPARE(QColor(differenceColour(200, 200)), lighter);
}

void TestFacesCompare::faceWithoutPhotoShowsTheModel() {
  setFlatFaces();  // F has no photo
  view_->setDisplay(FaceDisplay::Split);
  view_->setSplitPosition(0.6);
  QVERIFY(near(shot().pixelColor(at(FaceId::F, 0.3, 0.4)), kModel));
  view_->setDisplay(FaceDisplay::Difference);
  QTRY_VERIFY_WITH_TIMEOUT(view_->differenceUpToDate(), kTimeoutMs);
  QVERIFY(view_->differenceMaps()[faceIndex(FaceId::F)].isNull());
  QVERIFY(near(shot().pixelColor(at(FaceId::F, 0.3, 0.4)), kModel));
  // Without renderings there is nothing to compare: the photos, as in Photos display.
  view_->setRenderings({});
  QVERIFY(near(shot().pixelColor(at(FaceId::A, 0.8, 0.4)), kPhoto));
}

void TestFacesCompare::differenceTiming() {
  // Measured, not asserted: six 1024 px photos against 256 px renderings, on the calling thread.
  std::array<QImage, 6> photos, models;
  for (FaceId face : kAllFaces) {
    photos[faceIndex(face)] = sides({1024, 1024}, kPhoto, kModel);
    models[faceIndex(face)] = sides({256, 256}, kModel, kPhoto);
  }
  QElapsedTimer timer;
  timer.start();
  const auto maps = differenceHeatMaps(photos, models);
  const qint64 resampled = timer.restart();
  for (auto& model : models) model = model.scaled(1024, 1024);
  timer.restart();
  const auto same = differenceHeatMaps(photos, models);
  qInfo("heat maps of 6 x 1024^2 px: %lld ms with the model resampled from 256 px, %lld ms at the same size",
        resampled, timer.elapsed());
  QCOMPARE(maps[0].size(), QSize(1024, 1024));
  QCOMPARE(same[5].size(), QSize(1024, 1024));
}

QTEST_MAIN(TestFacesCompare)
#include "test_faces_compare.moc"
