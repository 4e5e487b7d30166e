// Texture > Photo-true Appearance in the editor (issue 17): on the demo block whose photos are tinted
// green (no wood is green, so a green surface can only come from the photos), the faces view, the 3D block
// and the cut panel show the photo-true surfaces once they land; an edit shows the procedural wood of the
// new model at once and the photo-true one again after; the choice is saved with the project and turned
// off again. Saves the editor's picture (photo_true_editor.png).
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QtTest>

#include "appearance/photo_true_source.hpp"
#include "appearance_controller.hpp"
#include "cut_view.hpp"
#include "demo_window.hpp"
#include "document.hpp"
#include "faces_controller.hpp"
#include "faces_view.hpp"
#include "params/parameter_schema.hpp"
#include "qt_image.hpp"
#include "viewport3d.hpp"
#include "window_grab.hpp"
#include "work_path.hpp"

using namespace kerf;

namespace {
constexpr int kTimeoutMs = 120000;

// Green over red, averaged over the opaque pixels of an image's middle half (1 for wood-coloured
// surfaces is far off: wood has more red than green).
double greenOverRed(const QImage& image) {
  const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
  double red = 0, green = 0;
  for (int y = rgba.height() / 4; y < 3 * rgba.height() / 4; ++y)
    for (int x = rgba.width() / 4; x < 3 * rgba.width() / 4; ++x) {
      const QColor c = rgba.pixelColor(x, y);
      if (c.alpha() < 255) continue;
      red += c.redF();
      green += c.greenF();
    }
  return green / std::max(red, 1e-6);
}

QImage greenTinted(const QImage& photo) {
  QImage out = photo.convertToFormat(QImage::Format_RGB888);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) {
      const QColor c = out.pixelColor(x, y);
      out.setPixelColor(x, y, QColor(c.red() / 4, c.green(), c.blue() / 4));
    }
  return out;
}
}  // namespace

class TestPhotoTrueView : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase();
  void actionIsInTheTextureMenuWithItsShortcut();
  void everyViewShowsThePhotoTrueSurfaces();
  void anEditShowsTheProceduralWoodUntilTheNewSurfacesLand();
  void theChoiceIsSavedAndTurnsOff();
  void reconstructSkipsTheProceduralTexture();
  void cleanupTestCase() { window_.reset(); }

 private:
  AppearanceController* appearance() const { return window_->appearance(); }
  bool facesAreGreen() const {
    for (const QImage& face : window_->facesView()->renderings())
      if (greenOverRed(face) < 1.5) return false;
    return true;
  }
  void waitUntilMade();

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TestPhotoTrueView::initTestCase() {
  QVERIFY(dir_.isValid());
  qputenv("KERF_AUTOSAVE_DIR", dir_.filePath("autosave").toUtf8());
  window_ = testing::openDemoWindow(dir_.filePath("demo"), 64, QSize(1400, 900), kTimeoutMs);
  QVERIFY(window_);
  Document* document = window_->document();
  // The demo's own photos, tinted, saved next to it (the project refers to photo files).
  for (FaceId face : kAllFaces) {
    const QString path = dir_.filePath(QStringLiteral("green_%1.png").arg(faceLetter(face)));
    const QImage green = greenTinted(document->photos()[faceIndex(face)]);
    QVERIFY(green.save(path));
    document->replacePhoto(face, path, green);
  }
  document->setCutEnabled(true);
  document->editCutPlane({0.0f, 30.0f, 20.0f}, true);
  QVERIFY(greenOverRed(window_->facesView()->renderings()[0]) < 1.0);  // the procedural wood
}

void TestPhotoTrueView::waitUntilMade() {
  QTRY_VERIFY_WITH_TIMEOUT(!appearance()->isWorking(), kTimeoutMs);
  QCoreApplication::processEvents();
}

void TestPhotoTrueView::actionIsInTheTextureMenuWithItsShortcut() {
  QAction* action = appearance()->photoTrueAction();
  QVERIFY(action->isCheckable());
  QVERIFY(action->isEnabled());  // the demo has photos
  QVERIFY(!action->isChecked());
  QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P));
  QVERIFY(action->toolTip().contains("photos") && action->toolTip().contains("rings"));
  bool inTextureMenu = false;
  for (QMenu* menu : window_->findChildren<QMenu*>())
    if (menu->title() == QStringLiteral("&Texture")) inTextureMenu = menu->actions().contains(action);
  QVERIFY(inTextureMenu);
}

void TestPhotoTrueView::everyViewShowsThePhotoTrueSurfaces() {
  QSignalSpy faces(appearance(), &AppearanceController::facesMade);
  QSignalSpy cut(appearance(), &AppearanceController::cutMade);
  const int undoSteps = window_->document()->undoStack()->count();
  appearance()->photoTrueAction()->trigger();
  QCOMPARE(window_->document()->appearance(), Appearance::Photo);
  QVERIFY(window_->document()->isModified());
  QCOMPARE(window_->document()->undoStack()->count(), undoSteps);  // a view choice, as the cut's visibility
  QTRY_VERIFY_WITH_TIMEOUT(faces.count() > 0 && cut.count() > 0, kTimeoutMs);
  waitUntilMade();
  QVERIFY(window_->faces()->showsAppearanceFaces());
  QVERIFY(facesAreGreen());
  // The same surfaces as kerf-cli's render-faces and export of the saved project (the model's seed).
  const auto model = window_->document()->model();
  const QImage shownA = window_->facesView()->renderings()[faceIndex(FaceId::A)];
  const QImage cliA =
      toQImage(makePhotoTrueAppearance(*model, *photoTrueSourceOf(window_->document()->project()))
                   ->renderFace(FaceId::A, {shownA.width(), shownA.height()}));
  QCOMPARE(shownA.convertToFormat(QImage::Format_RGB888), cliA.convertToFormat(QImage::Format_RGB888));
  QVERIFY(window_->cutView()->showsCutAppearance());
  QVERIFY(greenOverRed(window_->cutView()->grabFramebuffer()) > 1.5);
  window_->viewport()->refineNow();
  const QImage block = window_->viewport()->grabFramebuffer();
  QVERIFY(window_->viewport()->showsFaceAppearance());
  QVERIFY(window_->viewport()->showsCutAppearance());
  QVERIFY2(greenOverRed(block) > 1.3, qPrintable(QString::number(greenOverRed(block))));
  QVERIFY(grabWindowWithGl(window_.get()).save(testing::artifact("photo_true_editor")));
}

void TestPhotoTrueView::anEditShowsTheProceduralWoodUntilTheNewSurfacesLand() {
  QSignalSpy faces(appearance(), &AppearanceController::facesMade);
  Document* document = window_->document();
  const std::size_t ring = *parameterIndex("growth.ring_width");
  const float width = document->project().params.components(ring)[0];
  document->editParameter(ring, {width * 1.5f, 0, 0}, true);
  // At once: the new model's own wood, nowhere the old model's photo-true pictures.
  QVERIFY(!window_->faces()->showsAppearanceFaces());
  QVERIFY(!window_->cutView()->showsCutAppearance());
  QVERIFY(!window_->viewport()->showsFaceAppearance());
  QTRY_VERIFY_WITH_TIMEOUT(faces.count() > 0, kTimeoutMs);
  waitUntilMade();
  QVERIFY(facesAreGreen());
  QVERIFY(window_->cutView()->showsCutAppearance());
  // A new plane: the cut follows; going back to the old one comes from the kept cuts at once.
  QSignalSpy cut(appearance(), &AppearanceController::cutMade);
  const CutPlaneSetting before = document->cutPlane();
  document->editCutPlane({5.0f, 0.0f, 90.0f}, true);
  QVERIFY(!window_->cutView()->showsCutAppearance());
  QTRY_VERIFY_WITH_TIMEOUT(cut.count() > 0, kTimeoutMs);
  QVERIFY(window_->cutView()->showsCutAppearance());
  QVERIFY(greenOverRed(window_->cutView()->grabFramebuffer()) > 1.5);
  document->editCutPlane(before, true);
  QTRY_VERIFY_WITH_TIMEOUT(window_->cutView()->showsCutAppearance(),
                           2 * AppearanceController::kSettleMs + 1000);
}

void TestPhotoTrueView::theChoiceIsSavedAndTurnsOff() {
  const QString path = dir_.filePath("photo_true.kerf");
  window_->document()->saveAs(path);
  QFile file(path);
  QVERIFY(file.open(QIODevice::ReadOnly));
  QCOMPARE(QJsonDocument::fromJson(file.readAll()).object().value("appearance").toString(),
           QStringLiteral("photo"));
  appearance()->photoTrueAction()->trigger();
  QCOMPARE(window_->document()->appearance(), Appearance::Procedural);
  QVERIFY(!window_->faces()->showsAppearanceFaces());
  QVERIFY(!window_->cutView()->showsCutAppearance());
  QVERIFY(!facesAreGreen());
  QVERIFY(!appearance()->isWorking());
}

// With the photo-true appearance the procedural texture would not be seen: Reconstruct detects the rings
// and fits the field, skips the minute of texture inference, and the photo-true surfaces of the new field
// follow.
void TestPhotoTrueView::reconstructSkipsTheProceduralTexture() {
  appearance()->photoTrueAction()->trigger();
  QCOMPARE(window_->document()->appearance(), Appearance::Photo);
  WorkPath* path = window_->workPath();
  QList<ReconstructStage> started;
  QObject scope;
  connect(path, &WorkPath::stageStarted, &scope, [&](ReconstructStage stage) { started << stage; });
  QSignalSpy done(path, &WorkPath::reconstructed);
  QSignalSpy failed(path, &WorkPath::reconstructFailed);
  QSignalSpy faces(appearance(), &AppearanceController::facesMade);
  const auto before = window_->document()->model();
  path->reconstruct();
  QTRY_VERIFY_WITH_TIMEOUT(done.count() + failed.count() > 0, kTimeoutMs);
  QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
  QVERIFY(started.contains(ReconstructStage::Field));
  QVERIFY(!started.contains(ReconstructStage::Appearance));
  QVERIFY(window_->document()->model() != before);  // a new field
  QTRY_VERIFY_WITH_TIMEOUT(faces.count() > 0, kTimeoutMs);
  waitUntilMade();
  QVERIFY(window_->faces()->showsAppearanceFaces());
  QVERIFY(facesAreGreen());
}

QTEST_MAIN(TestPhotoTrueView)
#include "test_photo_true_view.moc"
