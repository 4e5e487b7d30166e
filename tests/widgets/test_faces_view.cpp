// FacesView: photos / model / blend display, zoom and pan, the cursor's face, pixel and block
// position, and drag and drop of photos and documents. Saves screenshots to test-artifacts/.
#include <QApplication>
#include <QDir>
#include <QDropEvent>
#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUrl>
#include <QWheelEvent>
#include <QtTest>
#include <memory>

#include "demo/demo_block.hpp"
#include "faces_view.hpp"
#include "qt_image.hpp"
#include "render/renderers.hpp"

using namespace kerf;

namespace {

const QString kArtifacts = QStringLiteral(KERF_TEST_ARTIFACTS);

}  // namespace

class TestFacesView : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void setFacesStaysCompatible();
  void displayModes();
  void blendLiesBetween();
  void wheelZoomsTowardsCursorAlongLadder();
  void panAndFit();
  void cursorPositionOnFaceA();
  void dropPhotoOnFace();
  void dropDocuments();
  void screenshots();

 private:
  QImage shot() { return view_->grab().toImage().convertToFormat(QImage::Format_RGB32); }
  void sendDrop(const QList<QUrl>& urls, QPointF at);

  Block block_;
  std::array<QImage, 6> photos_, renderings_;
  std::unique_ptr<FacesView> view_;
  QTemporaryDir dir_;
};

void TestFacesView::initTestCase() {
  const Project project = demoProject();
  const WoodModel model(project);
  block_ = project.block;
  const std::array<Image, 6> faces = renderFaces(model, 2.0f, 2);  // 80 x 80 px
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    renderings_[i] = toQImage(faces[i]);
    Image photo = faces[i];
    applyPhotoLook(photo, face, 7);
    photos_[i] = toQImage(photo);
  }
  view_ = std::make_unique<FacesView>();
  view_->resize(960, 720);
  view_->setBlock(block_);
  view_->setPhotos(photos_);
  view_->setRenderings(renderings_);
  view_->show();
  QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
}

void TestFacesView::setFacesStaysCompatible() {
  FacesView view;
  view.resize(480, 360);
  QVERIFY(!view.hasFaces());
  view.setFaces(renderings_, block_);
  QVERIFY(view.hasFaces());
  QCOMPARE(view.faces()[0], renderings_[0]);
  view.setDisplay(FaceDisplay::Model);  // one set: whatever the display, it is what is shown
  QCOMPARE(view.faces()[0], renderings_[0]);
  view.setFaces(photos_, block_);
  QCOMPARE(view.faces()[0], photos_[0]);
  view.clear();
  QVERIFY(!view.hasFaces());
}

void TestFacesView::displayModes() {
  const QPoint a = view_->faceRect(FaceId::A).center().toPoint();
  view_->setDisplay(FaceDisplay::Photos);
  QCOMPARE(view_->faces()[0], photos_[0]);
  const QImage photos = shot();
  view_->setDisplay(FaceDisplay::Model);
  QCOMPARE(view_->faces()[0], renderings_[0]);
  const QImage model = shot();
  view_->setDisplay(FaceDisplay::Blend);
  view_->setBlendOpacity(0.5);
  const QImage blend = shot();
  QVERIFY(photos.pixel(a) != model.pixel(a));
  QVERIFY(blend.pixel(a) != photos.pixel(a) && blend.pixel(a) != model.pixel(a));
  // Blend at opacity 0 and 1: the photos and the model.
  view_->setBlendOpacity(0.0);
  QCOMPARE(shot().pixel(a), photos.pixel(a));
  view_->setBlendOpacity(1.0);
  QCOMPARE(shot().pixel(a), model.pixel(a));
  view_->setBlendOpacity(0.5);
}

void TestFacesView::blendLiesBetween() {
  view_->setDisplay(FaceDisplay::Photos);
  const QImage photos = shot();
  view_->setDisplay(FaceDisplay::Model);
  const QImage model = shot();
  view_->setDisplay(FaceDisplay::Blend);
  view_->setBlendOpacity(0.5);
  const QImage blend = shot();
  double error = 0, spread = 0;
  int n = 0;
  for (FaceId face : kAllFaces) {
    const QRect r = view_->faceRect(face).toAlignedRect().adjusted(50, 50, -4, -4);  // off the label
    for (int y = r.top(); y < r.bottom(); y += 3)
      for (int x = r.left(); x < r.right(); x += 3) {
        const QColor p = photos.pixelColor(x, y), m = model.pixelColor(x, y), b = blend.pixelColor(x, y);
        for (auto [pc, mc, bc] :
             {std::tuple(p.red(), m.red(), b.red()), std::tuple(p.green(), m.green(), b.green()),
              std::tuple(p.blue(), m.blue(), b.blue())}) {
          QVERIFY(bc >= std::min(pc, mc) - 1 && bc <= std::max(pc, mc) + 1);
          error += std::abs(bc - 0.5 * (pc + mc));
          spread += std::abs(pc - mc);
          ++n;
        }
      }
  }
  qInfo() << "blend: mean distance from the midpoint" << error / n << "mean photo-model difference"
          << spread / n;
  QVERIFY(error / n < 1.5);
  QVERIFY(spread / n > 5);  // the two sets do differ
}

void TestFacesView::wheelZoomsTowardsCursorAlongLadder() {
  view_->fitToView();
  QCOMPARE(view_->zoom(), 1.0);
  const QPointF at = view_->faceRect(FaceId::A).center() + QPointF(30, -20);
  const auto before = view_->blockPointAt(at);
  QVERIFY(before);
  QSignalSpy zoomed(view_.get(), &FacesView::zoomChanged);
  QWheelEvent wheel(at, view_->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
  QApplication::sendEvent(view_.get(), &wheel);
  const auto& ladder = FacesView::zoomLadder();
  QCOMPARE(view_->zoom(), *std::upper_bound(ladder.begin(), ladder.end(), 1.0));
  QCOMPARE(zoomed.count(), 1);
  const auto after = view_->blockPointAt(at);
  QVERIFY(after);
  QVERIFY(glm::length(*after - *before) < 1e-3f);
  // Faces keep their proportions and stay a cross when zoomed.
  const QRectF a = view_->faceRect(FaceId::A), b = view_->faceRect(FaceId::B);
  QCOMPARE(b.left(), a.left());
  QVERIFY(b.bottom() <= a.top() && a.top() - b.bottom() < 5);  // the gap does not grow with the zoom
  // Half a notch (a touchpad) does nothing yet; the other half steps.
  QWheelEvent half(at, view_->mapToGlobal(at), QPoint(), QPoint(0, 60), Qt::NoButton, Qt::NoModifier,
                   Qt::NoScrollPhase, false);
  QApplication::sendEvent(view_.get(), &half);
  QCOMPARE(zoomed.count(), 1);
  QApplication::sendEvent(view_.get(), &half);
  QCOMPARE(zoomed.count(), 2);
  QVERIFY(view_->zoom() > 1.3);
  view_->fitToView();
}

void TestFacesView::panAndFit() {
  view_->setZoom(3.0);
  const QPointF start(400, 300), end(350, 330);
  const QRectF before = view_->faceRect(FaceId::A);
  auto send = [&](QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, pos, view_->mapToGlobal(pos), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(view_.get(), &event);
  };
  send(QEvent::MouseButtonPress, start, Qt::MiddleButton, Qt::MiddleButton);
  send(QEvent::MouseMove, end, Qt::NoButton, Qt::MiddleButton);
  send(QEvent::MouseButtonRelease, end, Qt::MiddleButton, Qt::NoButton);
  QCOMPARE(view_->faceRect(FaceId::A).topLeft(), before.topLeft() + (end - start));

  // Space + left drag pans too; a plain left drag does not.
  const QRectF mid = view_->faceRect(FaceId::A);
  send(QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  send(QEvent::MouseMove, end, Qt::NoButton, Qt::LeftButton);
  send(QEvent::MouseButtonRelease, end, Qt::LeftButton, Qt::NoButton);
  QCOMPARE(view_->faceRect(FaceId::A), mid);
  QTest::keyPress(view_.get(), Qt::Key_Space);
  send(QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  send(QEvent::MouseMove, end, Qt::NoButton, Qt::LeftButton);
  send(QEvent::MouseButtonRelease, end, Qt::LeftButton, Qt::NoButton);
  QTest::keyRelease(view_.get(), Qt::Key_Space);
  QCOMPARE(view_->faceRect(FaceId::A).topLeft(), mid.topLeft() + (end - start));

  // F fits; so does a double-click.
  QTest::keyClick(view_.get(), Qt::Key_F);
  QCOMPARE(view_->zoom(), 1.0);
  QCOMPARE(view_->pan(), QPointF());
  view_->setZoom(2.0);
  QTest::mouseDClick(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(300, 300));
  QCOMPARE(view_->zoom(), 1.0);
}

void TestFacesView::cursorPositionOnFaceA() {
  view_->fitToView();
  QSignalSpy spy(view_.get(), &FacesView::cursorPositionChanged);
  const QRectF a = view_->faceRect(FaceId::A);
  // The centre of pixel (20, 20) of the 80 px image: x = -9.75 mm, y = +9.75 mm on face A (z = +20 mm).
  const QPointF at(a.left() + a.width() * 20.5 / 80, a.top() + a.height() * 20.5 / 80);
  QMouseEvent move(QEvent::MouseMove, at, view_->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
  QApplication::sendEvent(view_.get(), &move);
  QCOMPARE(spy.count(), 1);
  const QString text = spy.takeFirst().at(0).toString();
  qInfo().noquote() << text;
  QVERIFY(text.startsWith("Face A"));
  QVERIFY(text.contains("pixel 20, 20"));  // of the 80 px image
  QVERIFY(text.contains("x -9.75") && text.contains("y 9.75") && text.contains("z 20.00 mm"));
  // In the gap between the faces or outside the cross: nothing.
  const QPointF gap(a.left() - 1, a.center().y());
  QVERIFY(!view_->faceAt(gap));
  QMouseEvent away(QEvent::MouseMove, QPointF(3, 3), view_->mapToGlobal(QPointF(3, 3)), Qt::NoButton,
                   Qt::NoButton, Qt::NoModifier);
  QApplication::sendEvent(view_.get(), &away);
  QCOMPARE(spy.count(), 1);
  QVERIFY(spy.takeFirst().at(0).toString().isEmpty());
  // Face D's centre is the block's bottom (y = -20).
  const auto d = view_->blockPointAt(view_->faceRect(FaceId::D).center());
  QVERIFY(d && std::abs(d->y + 20) < 1e-3f && std::abs(d->x) < 0.1f && std::abs(d->z) < 0.1f);
}

void TestFacesView::sendDrop(const QList<QUrl>& urls, QPointF at) {
  QMimeData mime;
  mime.setUrls(urls);
  QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(view_.get(), &enter);
  QDragMoveEvent move(at.toPoint(), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(view_.get(), &move);
  QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(view_.get(), &drop);
}

void TestFacesView::dropPhotoOnFace() {
  view_->fitToView();
  const QString photo = dir_.filePath("my photo.png");
  QVERIFY(photos_[2].save(photo));
  QSignalSpy photos(view_.get(), &FacesView::photoDropped);
  QSignalSpy documents(view_.get(), &FacesView::documentDropped);
  sendDrop({QUrl::fromLocalFile(photo)}, view_->faceRect(FaceId::C).center());
  QCOMPARE(photos.count(), 1);
  QCOMPARE(photos.at(0).at(0).value<FaceId>(), FaceId::C);
  QCOMPARE(photos.at(0).at(1).toString(), photo);
  // Outside the faces an image goes nowhere.
  sendDrop({QUrl::fromLocalFile(photo)}, QPointF(3, 3));
  QCOMPARE(photos.count(), 1);
  // Several photos at once: by their names.
  const QString a = dir_.filePath("A_col.jpg"), e = dir_.filePath("e.tif");
  QVERIFY(QFile::copy(photo, a) && QFile::copy(photo, e));
  sendDrop({QUrl::fromLocalFile(a), QUrl::fromLocalFile(e)}, QPointF(3, 3));
  QCOMPARE(photos.count(), 3);
  QCOMPARE(photos.at(1).at(0).value<FaceId>(), FaceId::A);
  QCOMPARE(photos.at(2).at(0).value<FaceId>(), FaceId::E);
  QCOMPARE(documents.count(), 0);
}

void TestFacesView::dropDocuments() {
  QSignalSpy photos(view_.get(), &FacesView::photoDropped);
  QSignalSpy documents(view_.get(), &FacesView::documentDropped);
  const QString project = dir_.filePath("wood.kerf");
  QFile file(project);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.close();
  sendDrop({QUrl::fromLocalFile(project)}, view_->faceRect(FaceId::A).center());
  QCOMPARE(documents.count(), 1);
  QCOMPARE(documents.at(0).at(0).toString(), project);
  const QString folder = dir_.filePath("sample");
  QVERIFY(QDir().mkpath(folder));
  sendDrop({QUrl::fromLocalFile(folder)}, QPointF(3, 3));  // anywhere
  QCOMPARE(documents.count(), 2);
  QCOMPARE(documents.at(1).at(0).toString(), folder);
  sendDrop({QUrl::fromLocalFile(dir_.filePath("notes.txt"))}, view_->faceRect(FaceId::A).center());
  QCOMPARE(documents.count(), 2);
  QCOMPARE(photos.count(), 0);
}

void TestFacesView::screenshots() {
  view_->fitToView();
  view_->setDisplay(FaceDisplay::Blend);
  view_->setBlendOpacity(0.5);
  view_->setCaption("Photos + model", "blend 50 %");
  QVERIFY(shot().save(kArtifacts + "/faces_view_blend.png"));
  view_->setDisplay(FaceDisplay::Photos);
  QVERIFY(shot().save(kArtifacts + "/faces_view_photos.png"));
  view_->setDisplay(FaceDisplay::Model);
  QVERIFY(shot().save(kArtifacts + "/faces_view_model.png"));
  view_->setDisplay(FaceDisplay::Blend);
  view_->setZoom(6.0, view_->faceRect(FaceId::A).topLeft());  // the A/B/C corner, magnified
  QVERIFY(shot().save(kArtifacts + "/faces_view_blend_zoom6.png"));
  view_->fitToView();
}

QTEST_MAIN(TestFacesView)
#include "test_faces_view.moc"
