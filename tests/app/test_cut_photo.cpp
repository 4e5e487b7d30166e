// A photo of the real cut, compared with the model's cut (issue 16 item 5, docs/editor.md "Comparing a
// photo of the cut"). On the demo block, the model's own cut is rendered and tinted green (no wood is
// green, so green on the panel can only come from the photo) and loaded as the cut photo: Split shows
// the photo left of the line and the model right of it; Difference is near black for the untinted render
// and bright for the tinted one, also against the photo-true cut; aligning, removing and loading are
// undo steps; another plane hides the photo and returning shows it; Save and Open bring it back with its
// alignment; a missing file and a file that is no image give an error naming the file. Saves
// cut_photo_split.png and cut_photo_difference.png.
#include <QActionGroup>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QPainter>
#include <QToolBar>
#include <QtTest>

#include "appearance_controller.hpp"
#include "cut_photo_controller.hpp"
#include "cut_photo_dialog.hpp"
#include "cut_view.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "log_board_controller.hpp"
#include "qt_image.hpp"
#include "render/board_wood.hpp"
#include "render/renderers.hpp"
#include "window_grab.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 120000;
const CutPlaneSetting kPlane{0.0f, 0.0f, 0.0f};  // parallel to faces C and E: a 40 x 40 mm square
constexpr float kPhotoPxPerMm = 6.0f;            // 240 px across the demo's 40 mm

// Green over red of the opaque pixels of `image` inside `area` (wood is redder than green: below 1).
double greenOverRed(const QImage& image, const QRect& area) {
  const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
  double red = 0, green = 0;
  for (int y = area.top(); y <= area.bottom(); ++y)
    for (int x = area.left(); x <= area.right(); ++x) {
      const QColor c = rgba.pixelColor(x, y);
      if (c.alpha() < 255) continue;
      red += c.redF();
      green += c.greenF();
    }
  return green / std::max(red, 1e-6);
}

QImage tinted(const QImage& image) {
  QImage out = image.convertToFormat(QImage::Format_RGB888);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) {
      const QColor c = out.pixelColor(x, y);
      out.setPixelColor(x, y, QColor(c.red() / 4, c.green(), c.blue() / 4));
    }
  return out;
}

// The share of a difference heat map's pixels brighter than `level` in their brightest channel.
double brightShare(const QImage& heat, int level) {
  const QImage rgb = heat.convertToFormat(QImage::Format_RGB32);
  long long bright = 0;
  for (int y = 0; y < rgb.height(); ++y)
    for (int x = 0; x < rgb.width(); ++x) {
      const QRgb c = rgb.pixel(x, y);
      if (std::max({qRed(c), qGreen(c), qBlue(c)}) > level) ++bright;
    }
  return double(bright) / std::max(1LL, static_cast<long long>(rgb.width()) * rgb.height());
}
}  // namespace

class TestCutPhoto : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void actionsAreInTheMenusWithShortcutsAndTips();
  void badFilesGiveAnErrorNamingThem();
  void splitShowsThePhotoLeftAndTheModelRight();
  void differenceIsNearZeroForTheModelsOwnCut();
  void alignmentIsAnUndoStep();
  void alignDialogTurnsAndMirrors();
  void anotherPlaneHidesThePhotoAndReturningShowsIt();
  void saveAndOpenRestoreThePhotoAndItsAlignment();
  void aMissingPhotoOnOpenNamesTheFile();
  void differenceFollowsThePhotoTrueCut();
  void showsWhereAnotherBoardDeparts();
  void differenceOfABoardCutFromALog();
  void cleanupTestCase() { window_.reset(); }

 private:
  CutPhotoController* controller() const { return window_->cutPhoto(); }
  CutView* view() const { return window_->cutView(); }
  Document* document() const { return window_->document(); }
  QString file(const QString& name) const { return dir_.filePath(name); }
  bool load(const QString& path);  // true when the photo is on the cut
  QRect cutArea() const { return view()->cutOutline().boundingRect().toRect().adjusted(3, 3, -3, -3); }
  // The cut panel's picture between fractions u0..u1 of the cut's width.
  double panelGreenOverRed(double u0, double u1) {
    const QRect a = cutArea();
    const QRect part(QPoint(a.left() + int(u0 * a.width()), a.top()),
                     QPoint(a.left() + int(u1 * a.width()), a.bottom()));
    return greenOverRed(view()->grabFramebuffer(), part);
  }
  void waitForDifference() {
    QTRY_VERIFY_WITH_TIMEOUT(view()->differenceUpToDate(), kTimeoutMs);
    QCoreApplication::processEvents();
    // The heat map is of the photo shown, never of the one before it (a late job of the earlier photo).
    QCOMPARE(view()->cutPhoto().difference.size(), view()->cutPhoto().photo.image.size());
  }

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
  double ownShare_ = 1.0;
};

bool TestCutPhoto::load(const QString& path) {
  controller()->loadCutPhoto(path);
  const auto shown = [&] {
    const auto& photo = document()->cutPhoto();
    return photo &&
           QString::fromStdString(photo->setup.source.string()) == QFileInfo(path).absoluteFilePath() &&
           controller()->showsDocumentPhoto() && view()->showsCutPhoto();
  };
  return QTest::qWaitFor(shown, kTimeoutMs);
}

void TestCutPhoto::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  window_ = testing::openDemoWindow(dir_.filePath("demo"), 64, QSize(1400, 900), kTimeoutMs);
  QVERIFY(window_);
  document()->setCutEnabled(true);
  document()->editCutPlane(kPlane, true);
  view()->zoomToFit();
  // The synthetic cut photos: the model's own cut, and the same tinted green.
  const Image own = renderCut(*document()->model(), kPlane.plane(), kPhotoPxPerMm);
  QCOMPARE(own.width, 240);
  const QImage ownImage = toQImage(own).convertToFormat(QImage::Format_RGB888);
  QVERIFY(ownImage.save(file("own_cut.png")));
  QVERIFY(tinted(ownImage).save(file("green_cut.png")));
}

void TestCutPhoto::actionsAreInTheMenusWithShortcutsAndTips() {
  QAction* load = controller()->loadAction();
  QCOMPARE(load->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
  QVERIFY(load->toolTip().contains("sawed") && load->toolTip().contains("cut"));
  QVERIFY(!controller()->alignAction()->isEnabled());  // nothing to align yet
  const QList<QAction*> displays = controller()->displayGroup()->actions();
  QCOMPARE(displays.size(), kCutDisplayCount);
  QCOMPARE(displays[2]->text(), QStringLiteral("Split"));
  QCOMPARE(displays[3]->text(), QStringLiteral("Difference"));
  QVERIFY(displays[3]->toolTip().contains("lighter") && displays[3]->toolTip().contains("darker"));
  QVERIFY(!displays[2]->isEnabled());
  bool inFileMenu = false, onCutBar = false;
  for (QMenu* menu : window_->findChildren<QMenu*>())
    if (menu->title() == QStringLiteral("&File")) inFileMenu = menu->actions().contains(load);
  for (QToolBar* bar : window_->findChildren<QToolBar*>())
    if (bar->objectName() == QStringLiteral("cutPhotoBar")) onCutBar = bar->actions().contains(load);
  QVERIFY(inFileMenu);
  QVERIFY(onCutBar);
}

void TestCutPhoto::badFilesGiveAnErrorNamingThem() {
  const int steps = document()->undoStack()->count();
  controller()->loadCutPhoto(file("no_such_cut.jpg"));
  QTRY_VERIFY_WITH_TIMEOUT(window_->lastError().contains("no_such_cut.jpg"), kTimeoutMs);
  QVERIFY2(window_->lastError().contains("does not exist"), qPrintable(window_->lastError()));
  QFile text(file("notes_cut.png"));
  QVERIFY(text.open(QIODevice::WriteOnly));
  text.write("measured the board at 27 mm\n");
  text.close();
  controller()->loadCutPhoto(file("notes_cut.png"));
  QTRY_VERIFY_WITH_TIMEOUT(window_->lastError().contains("notes_cut.png"), kTimeoutMs);
  QVERIFY(!document()->cutPhoto());
  QCOMPARE(document()->undoStack()->count(), steps);
}

void TestCutPhoto::splitShowsThePhotoLeftAndTheModelRight() {
  const int steps = document()->undoStack()->count();
  QVERIFY(load(file("green_cut.png")));
  QCOMPARE(document()->undoStack()->count(), steps + 1);
  QVERIFY(document()->cutPhoto()->plane == kPlane);
  QCOMPARE(view()->cutDisplay(), CutDisplay::Split);                 // loading shows the comparison
  QCOMPARE(view()->cutPhoto().photo.image.size(), QSize(240, 240));  // the photo's own resolution
  view()->setCutSplitPosition(0.5);
  QVERIFY(panelGreenOverRed(0.05, 0.45) > 1.5);  // the photo
  QVERIFY(panelGreenOverRed(0.55, 0.95) < 1.0);  // the model's wood
  // Dragging the line moves it; the photo follows.
  const QRect a = cutArea();
  const int y = a.center().y();
  QTest::mousePress(view(), Qt::LeftButton, {}, QPoint(int(*view()->cutSplitX()), y));
  QTest::mouseMove(view(), QPoint(a.left() + int(0.85 * a.width()), y));
  QTest::mouseRelease(view(), Qt::LeftButton, {}, QPoint(a.left() + int(0.85 * a.width()), y));
  QVERIFY(view()->cutSplitPosition() > 0.75);
  QVERIFY(panelGreenOverRed(0.55, 0.7) > 1.5);
  controller()->setDisplay(CutDisplay::Model);
  QVERIFY(panelGreenOverRed(0.05, 0.95) < 1.0);
  controller()->setDisplay(CutDisplay::Split);
}

void TestCutPhoto::differenceIsNearZeroForTheModelsOwnCut() {
  controller()->setDisplay(CutDisplay::Difference);
  waitForDifference();
  const double tintedShare = brightShare(view()->cutPhoto().difference, 32);
  QVERIFY(load(file("own_cut.png")));
  controller()->setDisplay(CutDisplay::Difference);
  waitForDifference();
  const double ownShare = brightShare(view()->cutPhoto().difference, 32);
  qInfo("heat map pixels brighter than 32: %.4f for the model's own cut, %.4f tinted", ownShare, tintedShare);
  QVERIFY(ownShare < 0.01);
  QVERIFY(tintedShare > 0.9);
  ownShare_ = ownShare;
  QVERIFY(view()->grabFramebuffer().save(testing::artifact("cut_photo_difference_own")));
}

void TestCutPhoto::alignmentIsAnUndoStep() {
  const CutPhoto before = *document()->cutPhoto();
  const QImage beforePicture = view()->cutPhoto().photo.image;
  const int steps = document()->undoStack()->count();
  controller()->setAlignment(before.setup.corners, 90, true);
  QCOMPARE(document()->undoStack()->count(), steps + 1);
  QCOMPARE(document()->undoStack()->undoText(), QStringLiteral("Align cut photo"));
  QTRY_VERIFY_WITH_TIMEOUT(controller()->showsDocumentPhoto(), kTimeoutMs);
  QCOMPARE(document()->cutPhoto()->setup.rotationDegrees, 90);
  QVERIFY(document()->cutPhoto()->setup.flip);
  QVERIFY(view()->cutPhoto().photo.image != beforePicture);  // turned and mirrored on the cut
  // Corners on one line make no surface: refused, nothing pushed.
  const std::array<glm::vec2, 4> line{glm::vec2(0, 0), glm::vec2(100, 0), glm::vec2(200, 0),
                                      glm::vec2(50, 0)};
  QVERIFY_THROWS_EXCEPTION(InputError, controller()->setAlignment(line, 0, false));
  QCOMPARE(document()->undoStack()->count(), steps + 1);
  document()->undoStack()->undo();
  QVERIFY(*document()->cutPhoto() == before);
  QTRY_VERIFY_WITH_TIMEOUT(controller()->showsDocumentPhoto(), kTimeoutMs);
  QVERIFY(view()->cutPhoto().photo.image == beforePicture);
  // Remove, and undo brings it back.
  controller()->removeCutPhoto();
  QVERIFY(!document()->cutPhoto());
  QVERIFY(!view()->showsCutPhoto());
  document()->undoStack()->undo();
  QTRY_VERIFY_WITH_TIMEOUT(controller()->showsDocumentPhoto() && view()->showsCutPhoto(), kTimeoutMs);
}

void TestCutPhoto::alignDialogTurnsAndMirrors() {
  const int steps = document()->undoStack()->index();
  controller()->alignAction()->trigger();
  CutPhotoDialog* dialog = nullptr;
  QTRY_VERIFY_WITH_TIMEOUT((dialog = window_->findChild<CutPhotoDialog*>()) != nullptr && dialog->isVisible(),
                           kTimeoutMs);
  dialog->setRotation(-90);  // the anticlockwise button
  dialog->setFlip(true);
  QVERIFY(dialog->grab().save(testing::artifact("cut_photo_align_dialog")));
  dialog->accept();
  QCOMPARE(document()->undoStack()->index(), steps + 1);
  QCOMPARE(document()->cutPhoto()->setup.rotationDegrees, 270);
  QVERIFY(document()->cutPhoto()->setup.flip);
  document()->undoStack()->undo();
  QCOMPARE(document()->cutPhoto()->setup.rotationDegrees, 0);
}

void TestCutPhoto::anotherPlaneHidesThePhotoAndReturningShowsIt() {
  QVERIFY(load(file("green_cut.png")));
  view()->setCutSplitPosition(0.5);
  QVERIFY(panelGreenOverRed(0.05, 0.45) > 1.5);
  document()->editCutPlane({8.0f, 0.0f, 0.0f}, true);
  QVERIFY(view()->cutPhotoStale());
  QVERIFY(!view()->showsCutPhoto());
  QVERIFY(panelGreenOverRed(0.05, 0.95) < 1.0);  // the model's wood on this plane, no photo
  document()->undoStack()->undo();
  QVERIFY(!view()->cutPhotoStale());
  QVERIFY(view()->showsCutPhoto());
  QVERIFY(panelGreenOverRed(0.05, 0.45) > 1.5);
  QVERIFY(grabWindowWithGl(window_.get()).save(testing::artifact("cut_photo_editor")));
  QVERIFY(view()->grabFramebuffer().save(testing::artifact("cut_photo_split")));
}

void TestCutPhoto::saveAndOpenRestoreThePhotoAndItsAlignment() {
  std::array<glm::vec2, 4> corners = document()->cutPhoto()->setup.corners;
  corners[1] += glm::vec2(-6.0f, 4.0f);  // a corner dragged in
  controller()->setAlignment(corners, 180, false);
  const CutPhoto saved = *document()->cutPhoto();
  const QString project = file("with_cut_photo.kerf");
  document()->saveAs(project);
  QFile json(project);
  QVERIFY(json.open(QIODevice::ReadOnly));
  const QJsonObject cut = QJsonDocument::fromJson(json.readAll()).object()["cut_photo"].toObject();
  QCOMPARE(cut["photo"].toString(), QStringLiteral("green_cut.png"));  // relative to the project

  QSignalSpy ready(window_.get(), &MainWindow::documentReady);
  window_->openDocument(project);
  QTRY_VERIFY_WITH_TIMEOUT(ready.count() > 0, kTimeoutMs);
  QTRY_VERIFY_WITH_TIMEOUT(controller()->showsDocumentPhoto() && view()->showsCutPhoto(), kTimeoutMs);
  QVERIFY(document()->cutPhoto().has_value());
  QVERIFY(*document()->cutPhoto() == saved);
  QVERIFY(!document()->cutPhotoImage().isNull());
  QVERIFY(!document()->isModified());
}

void TestCutPhoto::aMissingPhotoOnOpenNamesTheFile() {
  QFile in(file("with_cut_photo.kerf"));
  QVERIFY(in.open(QIODevice::ReadOnly));
  QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
  QJsonObject cut = root["cut_photo"].toObject();
  cut["photo"] = QStringLiteral("sawn_and_lost.jpg");
  root["cut_photo"] = cut;
  QFile out(file("lost_cut_photo.kerf"));
  QVERIFY(out.open(QIODevice::WriteOnly));
  out.write(QJsonDocument(root).toJson());
  out.close();
  window_->openDocument(file("lost_cut_photo.kerf"));
  QTRY_VERIFY_WITH_TIMEOUT(window_->lastError().contains("sawn_and_lost.jpg"), kTimeoutMs);
  QVERIFY(document()->cutPhoto().has_value());  // kept in the project, to save as it was
  QVERIFY(!view()->showsCutPhoto());
}

void TestCutPhoto::differenceFollowsThePhotoTrueCut() {
  // Back to a photo on the cut, and the photo-true appearance on: the model's side is the photo-true cut.
  QVERIFY(load(file("own_cut.png")));
  QSignalSpy cutMade(window_->appearance(), &AppearanceController::cutMade);
  window_->appearance()->photoTrueAction()->trigger();
  QTRY_VERIFY_WITH_TIMEOUT(view()->showsCutAppearance(), kTimeoutMs);
  controller()->setDisplay(CutDisplay::Difference);
  waitForDifference();
  QVERIFY(view()->cutPhoto().differenceOfAppearance);
  const double procedural = brightShare(view()->cutPhoto().difference, 32);
  // The photo-true cut itself as the cut photo: near zero against it.
  QVERIFY(view()->shownCutAppearance().save(file("photo_true_cut.png")));
  QVERIFY(load(file("photo_true_cut.png")));
  controller()->setDisplay(CutDisplay::Difference);
  waitForDifference();
  QVERIFY(view()->cutPhoto().differenceOfAppearance);
  const double own = brightShare(view()->cutPhoto().difference, 32);
  qInfo(
      "against the photo-true cut, pixels brighter than 32: %.4f for its own image, %.4f for the procedural "
      "cut",
      own, procedural);
  QVERIFY(own < 0.01);
  QVERIFY(procedural > own + 0.1);
  window_->appearance()->photoTrueAction()->trigger();  // off again: back to the procedural wood
}

void TestCutPhoto::showsWhereAnotherBoardDeparts() {
  // The "real" board: the demo's wood with the pith tilted 3 degrees more, so its rings drift away from
  // the model's across the cut. The picture (split | difference) is docs/images/cut_photo_compare.png.
  QVERIFY(!view()->showsCutAppearance());
  Project real = document()->project();
  real.params.pithTilt += 3.0f;
  const WoodModel realWood(real);
  const QImage realCut = toQImage(renderCut(realWood, kPlane.plane(), kPhotoPxPerMm));
  QVERIFY(realCut.convertToFormat(QImage::Format_RGB888).save(file("real_cut.png")));
  QVERIFY(load(file("real_cut.png")));
  view()->setCutSplitPosition(0.5);
  const QImage split = view()->grabFramebuffer();
  controller()->setDisplay(CutDisplay::Difference);
  waitForDifference();
  const double share = brightShare(view()->cutPhoto().difference, 32);
  qInfo("pith tilted 3 degrees more: heat map pixels brighter than 32: %.4f", share);
  QVERIFY(share > ownShare_ + 0.05);
  const QImage difference = view()->grabFramebuffer();
  QImage both(split.width() + 8 + difference.width(), split.height(), QImage::Format_RGB32);
  both.fill(QColor(38, 38, 40));
  QPainter painter(&both);
  painter.drawImage(0, 0, split);
  painter.drawImage(split.width() + 8, 0, difference);
  painter.end();
  QVERIFY(both.save(testing::artifact("cut_photo_compare")));
}

QTEST_MAIN(TestCutPhoto)
#include "test_cut_photo.moc"

// Log mode: the cut panel shows a board cut from a log (its knot model in GLSL); Difference compares the
// photo with that board's cut, rendered on the CPU (render/board_wood.hpp renderBoardCut), not with the
// block model's. The board's own cut loaded as the photo: near black; tinted green: bright.
void TestCutPhoto::differenceOfABoardCutFromALog() {
  window_->logBoard()->openRandomLog(7);
  QTRY_VERIFY_WITH_TIMEOUT(document()->log().has_value() && view()->boardWood(), kTimeoutMs);
  document()->setCutEnabled(true);
  document()->editCutPlane(kPlane, true);
  view()->zoomToFit();
  // The board's wood is made again in the background after the log lands (latest wins): settle first.
  QTest::qWait(500);
  QTRY_VERIFY_WITH_TIMEOUT(view()->boardWood(), kTimeoutMs);
  const std::shared_ptr<const BoardWood> wood = view()->boardWood();
  const glm::vec3 size = document()->project().block.size();
  const float pxPerMm = std::min(3.0f, 900.0f / std::max({size.x, size.y, size.z}));
  const QImage own =
      toQImage(renderBoardCut(*wood, kPlane.plane(), pxPerMm)).convertToFormat(QImage::Format_RGB888);
  QVERIFY(own.save(file("board_cut.png")));
  QVERIFY(tinted(own).save(file("board_cut_green.png")));

  QVERIFY(load(file("board_cut_green.png")));
  controller()->setDisplay(CutDisplay::Difference);
  waitForDifference();
  QVERIFY(view()->cutPhoto().differenceBoard == view()->boardWood());
  const double tintedShare = brightShare(view()->cutPhoto().difference, 32);
  QVERIFY(load(file("board_cut.png")));
  controller()->setDisplay(CutDisplay::Difference);
  waitForDifference();
  const double ownShare = brightShare(view()->cutPhoto().difference, 32);
  qInfo("log mode, %.2f px/mm: heat map pixels brighter than 32: %.4f for the board's own cut, %.4f tinted",
        pxPerMm, ownShare, tintedShare);
  QVERIFY(ownShare < 0.02);
  QVERIFY(tintedShare > 0.9);
  QVERIFY(view()->grabFramebuffer().save(testing::artifact("cut_photo_difference_log")));
}
