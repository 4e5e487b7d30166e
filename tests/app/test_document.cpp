// The editor's document: undo steps (merged drags), validation, save/reopen, autosave.
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "autosave.hpp"
#include "demo/demo_block.hpp"
#include "document.hpp"
#include "fit_job.hpp"
#include "util/error.hpp"

using namespace kerf;

namespace {

// A ceiling for a wait that ends on a signal, not a measure: a busy machine must not fail the test.
constexpr int kTimeoutMs = 60000;
std::size_t indexOf(const char* id) {
  return *parameterIndex(id);
}
std::array<float, 3> scalar(float v) {
  return {v, 0, 0};
}
}  // namespace

class DocumentTest : public QObject {
  Q_OBJECT

 private slots:
  void init() { document_.reset(demoProject(), {}, "demo", {}); }

  void sliderDragIsOneUndoStep() {
    const std::size_t ring = indexOf("growth.ring_width");
    const float before = document_.project().params.ringWidth;
    QSignalSpy modelChanged(&document_, &Document::modelChanged);
    document_.editParameter(ring, scalar(3.5f), false);
    document_.editParameter(ring, scalar(4.0f), false);
    document_.editParameter(ring, scalar(4.5f), true);
    QCOMPARE(document_.undoStack()->count(), 1);
    QCOMPARE(document_.project().params.ringWidth, 4.5f);
    QCOMPARE(modelChanged.count(), 3);
    QVERIFY(document_.isModified());
    QCOMPARE(document_.undoStack()->undoText(), QString("Change Average ring width"));
    document_.undoStack()->undo();
    QCOMPARE(document_.project().params.ringWidth, before);
    QVERIFY(!document_.isModified());
    document_.undoStack()->redo();
    QCOMPARE(document_.project().params.ringWidth, 4.5f);
    // The model the views get is rebuilt from the parameters.
    QCOMPARE(document_.model()->params().ringWidth, 4.5f);
  }

  void separateEditsAreSeparateSteps() {
    const std::size_t ring = indexOf("growth.ring_width");
    document_.editParameter(ring, scalar(3.5f), true);
    document_.editParameter(ring, scalar(4.0f), true);
    document_.editParameter(indexOf("rays.density"), scalar(0.2f), true);
    QCOMPARE(document_.undoStack()->count(), 3);
  }

  void dragBackToTheStartLeavesNoStep() {
    const std::size_t ring = indexOf("growth.ring_width");
    const float before = document_.project().params.ringWidth;
    document_.editParameter(ring, scalar(before + 1), false);
    document_.editParameter(ring, scalar(before), true);
    QCOMPARE(document_.undoStack()->count(), 0);
    document_.editParameter(ring, scalar(before), true);  // no change at all
    QCOMPARE(document_.undoStack()->count(), 0);
  }

  void badValuesAreRefusedBeforeTheUndoStack() {
    QVERIFY_THROWS_EXCEPTION(InputError,
                             document_.editParameter(indexOf("rays.density"), scalar(7.0f), true));
    QVERIFY_THROWS_EXCEPTION(
        InputError, document_.editParameter(indexOf("growth.ring_width"), scalar(std::nanf("")), true));
    QCOMPARE(document_.undoStack()->count(), 0);
  }

  void colourAndPresetEdits() {
    document_.editParameter(indexOf("color.latewood"), {0.1f, 0.2f, 0.3f}, true);
    QCOMPARE(document_.project().params.latewoodColor, glm::vec3(0.1f, 0.2f, 0.3f));
    WoodParameters preset = document_.project().params;
    preset.poreDensityEarly = 0, preset.poreDensityLate = 0, preset.ringWidth = 5;
    document_.applyParameters(preset, "Apply preset Spruce");
    QCOMPARE(document_.undoStack()->count(), 2);
    QCOMPARE(document_.project().params.ringWidth, 5.0f);
    document_.undoStack()->undo();
    QCOMPARE(document_.project().params.ringWidth, demoProject().params.ringWidth);
    QCOMPARE(document_.project().params.latewoodColor, glm::vec3(0.1f, 0.2f, 0.3f));
  }

  void growthFieldIsOneUndoStep() {
    const WoodParameters beforeParams = document_.project().params;
    const std::optional<GrowthRates> beforeRates = document_.project().rates;
    WoodParameters params = beforeParams;
    params.ringWidth = beforeParams.ringWidth * 1.5f;
    params.pithTilt = beforeParams.pithTilt + 2.0f;
    const PithAxis axis = PithAxis::fromAngles(params.pithOrigin, params.pithTilt, params.pithAzimuth);
    GrowthRates rates = GrowthRates::uniform(document_.project().block, axis);
    for (std::size_t i = 0; i < rates.rates.size(); ++i) rates.rates[i] = 0.5f + 0.001f * (i % 100);
    QSignalSpy modelChanged(&document_, &Document::modelChanged);
    document_.applyGrowthField(params, rates, "Fit growth field");
    QCOMPARE(document_.undoStack()->count(), 1);
    QCOMPARE(document_.undoStack()->undoText(), QString("Fit growth field"));
    QCOMPARE(modelChanged.count(), 1);
    QVERIFY(document_.project().rates.has_value());
    QCOMPARE(document_.project().rates->rates, rates.rates);
    QCOMPARE(document_.project().params.ringWidth, params.ringWidth);
    // The model is built from the explicit rates, not from rates synthesised from the parameters.
    QCOMPARE(document_.model()->field().rates().rates, rates.rates);
    QCOMPARE(document_.model()->params().pithTilt, params.pithTilt);

    document_.undoStack()->undo();  // both come back together
    QVERIFY(document_.project().params == beforeParams);
    QCOMPARE(document_.project().rates.has_value(), beforeRates.has_value());
    QVERIFY(document_.model()->field().rates().rates != rates.rates);
    QVERIFY(!document_.isModified());
    document_.undoStack()->redo();
    QCOMPARE(document_.model()->field().rates().rates, rates.rates);

    // Bad rates are refused before they reach the undo stack.
    GrowthRates bad = rates;
    bad.rates.pop_back();
    QVERIFY_THROWS_EXCEPTION(InputError, document_.applyGrowthField(params, bad, "bad"));
    QCOMPARE(document_.undoStack()->count(), 1);
  }

  // A fitted field brings its knots (Mokume Sec. 5.2.4); they come and go with it in one undo step.
  void fittedKnotsAreUndoneWithTheField() {
    const WoodParameters params = document_.project().params;
    const std::vector<BlockKnot> before = document_.project().knots;
    const std::vector<BlockKnot> knots = {BlockKnot{0, {12, 0, -75}, {0, 0.2f, 1}, 0.1f}};
    const int steps = document_.undoStack()->count();
    document_.applyGrowthField(params, document_.project().rates, "Fit growth field", knots);
    QCOMPARE(document_.undoStack()->count(), steps + 1);
    QVERIFY(document_.project().knots == knots);
    QCOMPARE(document_.model()->knots().knots().size(), std::size_t(1));
    document_.undoStack()->undo();
    QVERIFY(document_.project().knots == before);
    QCOMPARE(document_.model()->knots().knots().size(), before.size());
    // A bad knot is refused, naming it, before it reaches the undo stack.
    const std::vector<BlockKnot> bad = {BlockKnot{0, {0, 0, 0}, {0, 0, 0}, 0.1f}};
    QVERIFY_THROWS_EXCEPTION(InputError, document_.applyGrowthField(params, std::nullopt, "bad", bad));
    QCOMPARE(document_.undoStack()->count(), steps + 1);
  }

  void ringJobsSayWhatIsMissing() {
    const Block block = document_.project().block;
    QVERIFY_THROWS_EXCEPTION(InputError, detectRings({}, block, "classical"));  // no photos
    QVERIFY_THROWS_EXCEPTION(InputError,
                             fitGrowthField({}, block, document_.project().params));  // no contours
  }

  void cutPlaneDragIsOneStep() {
    QSignalSpy changed(&document_, &Document::cutPlaneChanged);
    document_.editCutPlane({1, 0, 0}, false);
    document_.editCutPlane({2, 10, 0}, false);
    document_.editCutPlane({3, 15, 0}, true);
    QCOMPARE(document_.undoStack()->count(), 1);
    QCOMPARE(document_.cutPlane(), (CutPlaneSetting{3, 15, 0}));
    QCOMPARE(changed.count(), 3);
    document_.undoStack()->undo();
    QCOMPARE(document_.cutPlane(), *demoProject().cutPlane);
  }

  void photoReplacementIsUndoable() {
    QImage red(8, 8, QImage::Format_RGB32);
    red.fill(Qt::red);
    document_.replacePhoto(FaceId::C, "/tmp/c.png", red);
    QCOMPARE(document_.photos()[2].pixelColor(1, 1), QColor(Qt::red));
    QCOMPARE(QString::fromStdString(document_.project().facePhotos[2].string()), QString("/tmp/c.png"));
    document_.undoStack()->undo();
    QVERIFY(document_.photos()[2].isNull());
    QVERIFY(document_.project().facePhotos[2].empty());
  }

  void saveAndReopenRoundTrip() {
    QTemporaryDir dir;
    document_.editParameter(indexOf("growth.ring_width"), scalar(2.25f), true);
    document_.editCutPlane({4, 30, 15}, true);
    document_.setCutEnabled(true);
    QVERIFY(document_.isModified());
    const QString path = dir.filePath("saved.kerf");
    document_.saveAs(path);
    QVERIFY(!document_.isModified());
    QCOMPARE(document_.filePath(), path);
    QCOMPARE(document_.name(), QString("saved"));
    const Project reopened = loadProject(path.toStdString());
    QCOMPARE(reopened.params, document_.project().params);
    QVERIFY(reopened.cutPlane.has_value());
    QCOMPARE(*reopened.cutPlane, (CutPlaneSetting{4, 30, 15}));
    QVERIFY(reopened.cutEnabled);
    QVERIFY_THROWS_EXCEPTION(InputError, document_.saveAs(dir.filePath("missing/folder/x.kerf")));
  }

  void autosaveKeepsUnsavedWorkAndCleansUp() {
    QTemporaryDir dir;
    Autosave autosave(&document_, dir.path(), 60000);
    autosave.saveNow();
    QVERIFY(!QFile::exists(autosave.currentFile()));  // nothing unsaved yet
    document_.editParameter(indexOf("growth.ring_width"), scalar(6.0f), true);
    autosave.saveNow();
    QVERIFY(QFile::exists(autosave.currentFile()));
    const Project recovered = loadProject(autosave.currentFile().toStdString());
    QCOMPARE(recovered.params.ringWidth, 6.0f);
    QCOMPARE(Autosave::originalPathOf(autosave.currentFile()), QString());
    // Another session's instance sees this copy as a leftover; this one does not.
    Autosave other(&document_, dir.path(), 60000);
    QCOMPARE(other.leftovers(), QStringList{QFileInfo(autosave.currentFile()).absoluteFilePath()});
    QVERIFY(autosave.leftovers().isEmpty());
    document_.undoStack()->undo();  // back to clean: the copy goes away
    autosave.saveNow();
    QVERIFY(!QFile::exists(autosave.currentFile()));
  }

  // The timer's path: written on a worker thread, not rewritten while nothing changes, removed when the
  // document is back to clean.
  void autosaveTimerWritesOnlyChanges() {
    QTemporaryDir dir;
    Autosave autosave(&document_, dir.path(), 40);
    QSignalSpy saved(&autosave, &Autosave::saved);
    document_.editParameter(indexOf("growth.ring_width"), scalar(5.0f), true);
    QTRY_COMPARE_WITH_TIMEOUT(saved.count(), 1, kTimeoutMs);
    QVERIFY(QFile::exists(autosave.currentFile()));
    QCOMPARE(loadProject(autosave.currentFile().toStdString()).params.ringWidth, 5.0f);
    QTest::qWait(300);  // several ticks, nothing changed
    QCOMPARE(saved.count(), 1);
    document_.editParameter(indexOf("growth.ring_width"), scalar(4.0f), true);
    QTRY_COMPARE_WITH_TIMEOUT(saved.count(), 2, kTimeoutMs);
    QCOMPARE(loadProject(autosave.currentFile().toStdString()).params.ringWidth, 4.0f);
    document_.undoStack()->undo();
    document_.undoStack()->undo();
    QTRY_VERIFY_WITH_TIMEOUT(!QFile::exists(autosave.currentFile()), kTimeoutMs);
  }

 private:
  Document document_;
};

QTEST_MAIN(DocumentTest)
#include "test_document.moc"
