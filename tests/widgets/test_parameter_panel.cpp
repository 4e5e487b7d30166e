// ParameterPanel and CutPlaneControls under a virtual X server: rows built from the schema, the
// parameterEdited / settingEdited signals with their finished flags for mouse drags, keys, typed values,
// resets, colour picks, presets and filtering. Screenshots go to KERF_TEST_ARTIFACTS for a human look.
#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStyleOptionSlider>
#include <QToolButton>
#include <QToolTip>
#include <QVBoxLayout>
#include <QtTest>
#include <cmath>
#include <glm/geometric.hpp>

#include "../timing_checks.hpp"
#include "cut_plane_controls.hpp"
#include "parameter_panel.hpp"
#include "params/builtin_presets.hpp"

using namespace kerf;

namespace {

int indexOf(const char* id) {
  const auto index = parameterIndex(id);
  if (!index) qFatal("no parameter %s", id);
  return static_cast<int>(*index);
}

template <typename T>
T* child(QWidget* parent, const QString& name) {
  T* found = parent->findChild<T*>(name);
  if (!found) qFatal("no child %s", qPrintable(name));
  return found;
}

QPoint handleCenter(QSlider* slider) {
  QStyleOptionSlider option;
  option.initFrom(slider);
  option.orientation = slider->orientation();
  option.minimum = slider->minimum();
  option.maximum = slider->maximum();
  option.sliderPosition = slider->sliderPosition();
  option.sliderValue = slider->value();
  option.subControls = QStyle::SC_All;
  return slider->style()
      ->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider)
      .center();
}

void sendMouse(QWidget* widget, QEvent::Type type, QPoint pos, Qt::MouseButtons buttons) {
  QMouseEvent event(type, pos, widget->mapToGlobal(pos),
                    type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton, buttons, Qt::NoModifier);
  QApplication::sendEvent(widget, &event);
}

// Presses the slider's handle, drags it right by `steps` moves of `dx` pixels, releases.
void dragSlider(QSlider* slider, int steps, int dx) {
  QPoint pos = handleCenter(slider);
  sendMouse(slider, QEvent::MouseButtonPress, pos, Qt::LeftButton);
  for (int i = 0; i < steps; ++i) {
    pos.rx() += dx;
    sendMouse(slider, QEvent::MouseMove, pos, Qt::LeftButton);
  }
  sendMouse(slider, QEvent::MouseButtonRelease, pos, Qt::NoButton);
}

struct Edit {
  int index;
  std::array<float, 3> value;
  bool finished;
};

Edit editAt(const QSignalSpy& spy, int i) {
  const QList<QVariant>& args = spy.at(i);
  return {args.at(0).toInt(), args.at(1).value<std::array<float, 3>>(), args.at(2).toBool()};
}

CutPlaneSetting settingAt(const QSignalSpy& spy, int i) {
  return spy.at(i).at(0).value<CutPlaneSetting>();
}

// Clicks a check box or radio button on its indicator (its centre may lie in empty, stretched space).
void clickIndicator(QAbstractButton* button) {
  QTest::mouseClick(button, Qt::LeftButton, {}, QPoint(8, button->height() / 2));
}

void typeInto(QAbstractSpinBox* field, const QString& text) {
  field->setFocus();
  field->selectAll();
  QTest::keyClicks(field, text);
  QTest::keyClick(field, Qt::Key_Return);
}

void saveShot(QWidget* widget, const QString& name) {
  const QString dir = QStringLiteral(KERF_TEST_ARTIFACTS);
  QDir().mkpath(dir);
  const QString path = dir + QLatin1Char('/') + name;
  QTest::qWait(20);  // pending layout requests
  QVERIFY2(widget->grab().save(path), qPrintable(path));
  qInfo() << "screenshot:" << path;
}

}  // namespace

class ParameterPanelTest : public QObject {
  Q_OBJECT

 private slots:
  void oneRowPerSchemaParameterBuiltFast() {
    QElapsedTimer timer;
    timer.start();
    ParameterPanel panel;
    const qint64 buildMs = timer.elapsed();
    panel.resize(460, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    qInfo() << "ParameterPanel with" << panel.rowCount() << "rows built in" << buildMs << "ms";
    QCOMPARE(panel.rowCount(), static_cast<int>(parameterSchema().size()));
    if (kerf::testing::timingChecks()) QVERIFY(buildMs < 300);  // typically ~30 ms
    for (std::size_t i = 0; i < parameterSchema().size(); ++i) {
      const QString id = QString::fromUtf8(parameterSchema()[i].id.data(), parameterSchema()[i].id.size());
      QWidget* row = panel.row(static_cast<int>(i));
      QVERIFY(row);
      QCOMPARE(row->objectName(), QStringLiteral("row:") + id);
      QVERIFY(panel.rowMatchesFilter(static_cast<int>(i)));
      QVERIFY(panel.findChild<QToolButton*>(QStringLiteral("reset:") + id));
    }
    // Every section has a readable title.
    for (const char* group :
         {"growth", "rings", "color", "distortion", "fibers", "pores", "rays", "faces", "model"}) {
      auto* header = child<QToolButton>(&panel, QStringLiteral("section:") + group);
      QVERIFY(!header->text().isEmpty());
      QVERIFY(header->text() != QLatin1String(group));
    }
    // Units are shown as suffixes; tooltips carry the schema text and the ranges.
    auto* ringField = child<QDoubleSpinBox>(&panel, "field:growth.ring_width");
    QCOMPARE(ringField->suffix(), QStringLiteral(" mm"));
    QCOMPARE(ringField->maximum(), 100.0);  // the hard range, not the slider's 10
    QCOMPARE(child<QDoubleSpinBox>(&panel, "field:growth.pith_tilt")->suffix(), QStringLiteral("°"));
    const QString tip = child<QSlider>(&panel, "slider:growth.ring_width")->toolTip();
    QVERIFY(tip.contains("Average width of one annual ring"));
    QVERIFY(tip.contains("0.5 – 10 mm"));
    QVERIFY(tip.contains("0.05 – 100 mm"));
  }

  void setParametersDoesNotEmitNorRebuild() {
    ParameterPanel panel;
    QSignalSpy spy(&panel, &ParameterPanel::parameterEdited);
    const int widgetsBefore = panel.findChildren<QWidget*>().size();
    WoodParameters p;
    p.ringWidth = 4.5f;
    p.earlywoodColor = {0.5f, 0.25f, 0.125f};
    p.pithOrigin = {1, 2, -30};
    p.seed = 42;
    p.faceTintB = {1.2f, 1.0f, 0.8f};
    p.poreRadiusEarly = 0.7f;  // outside the slider's travel, inside the hard range
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < 20; ++i) {
      p.rayWidth = 0.05f + 0.01f * i;
      panel.setParameters(p);
    }
    qInfo() << "20 x setParameters:" << timer.elapsed() << "ms";
    QCOMPARE(spy.count(), 0);
    QCOMPARE(panel.findChildren<QWidget*>().size(), widgetsBefore);
    QCOMPARE(panel.parameters(), p);
    QCOMPARE(child<QDoubleSpinBox>(&panel, "field:growth.ring_width")->value(), 4.5);
    QCOMPARE(child<QLineEdit>(&panel, "hex:color.earlywood")->text(), QStringLiteral("#804020"));
    QCOMPARE(child<QDoubleSpinBox>(&panel, "field:growth.pith_origin:2")->value(), -30.0);
    QCOMPARE(child<QSpinBox>(&panel, "field:model.seed")->value(), 42);
    QCOMPARE(child<QDoubleSpinBox>(&panel, "field:faces.tint_b:0")->value(), 1.2);
    QCOMPARE(child<QDoubleSpinBox>(&panel, "field:pores.radius_earlywood")->value(), 0.7);
    auto* poreSlider = child<QSlider>(&panel, "slider:pores.radius_earlywood");
    QCOMPARE(poreSlider->value(), poreSlider->maximum());  // pinned at the end of its travel
    QVERIFY(child<QToolButton>(&panel, "reset:growth.ring_width")->isEnabled());
    QVERIFY(!child<QToolButton>(&panel, "reset:rings.transition")->isEnabled());
  }

  void sliderDragEmitsIntermediateThenFinished() {
    ParameterPanel panel;
    panel.resize(460, 700);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QSignalSpy spy(&panel, &ParameterPanel::parameterEdited);
    auto* slider = child<QSlider>(&panel, "slider:rings.latewood_fraction");
    dragSlider(slider, 5, 6);
    QVERIFY(spy.count() >= 2);
    const int index = indexOf("rings.latewood_fraction");
    for (int i = 0; i + 1 < spy.count(); ++i) {
      const Edit e = editAt(spy, i);
      QCOMPARE(e.index, index);
      QVERIFY2(!e.finished, "intermediate drag values are not finished");
    }
    const Edit last = editAt(spy, spy.count() - 1);
    QCOMPARE(last.index, index);
    QVERIFY(last.finished);
    QVERIFY(last.value[0] > 0.3f);  // dragged right from the default
    QCOMPARE(last.value[0], editAt(spy, spy.count() - 2).value[0]);
    QCOMPARE(panel.parameters().latewoodFraction, last.value[0]);
    // The field follows the slider.
    QCOMPARE(float(child<QDoubleSpinBox>(&panel, "field:rings.latewood_fraction")->value()), last.value[0]);

    // A press and release without movement emits nothing.
    spy.clear();
    dragSlider(slider, 0, 0);
    QCOMPARE(spy.count(), 0);
  }

  void sliderKeysEmitFinishedSteps() {
    ParameterPanel panel;
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QSignalSpy spy(&panel, &ParameterPanel::parameterEdited);
    auto* slider = child<QSlider>(&panel, "slider:growth.ring_width");
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_Right);
    QCOMPARE(spy.count(), 1);
    Edit e = editAt(spy, 0);
    QCOMPARE(e.index, indexOf("growth.ring_width"));
    QVERIFY(e.finished);
    QVERIFY(e.value[0] > 3.0f && e.value[0] < 3.2f);  // one small (logarithmic) step
    QTest::keyClick(slider, Qt::Key_PageUp);
    QCOMPARE(spy.count(), 2);
    e = editAt(spy, 1);
    QVERIFY(e.finished);
    QVERIFY(e.value[0] > 3.3f);
    QTest::keyClick(slider, Qt::Key_Left);
    QCOMPARE(spy.count(), 3);
    QVERIFY(editAt(spy, 2).finished);
    QVERIFY(editAt(spy, 2).value[0] < e.value[0]);
    QTest::keyClick(slider, Qt::Key_End);
    QCOMPARE(editAt(spy, spy.count() - 1).value[0], 10.0f);  // the end of the soft range
  }

  void typedValueEmitsFinished() {
    ParameterPanel panel;
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QSignalSpy spy(&panel, &ParameterPanel::parameterEdited);
    auto* field = child<QDoubleSpinBox>(&panel, "field:growth.ring_width");
    typeInto(field, "4.5");
    QCOMPARE(spy.count(), 1);
    Edit e = editAt(spy, 0);
    QCOMPARE(e.index, indexOf("growth.ring_width"));
    QCOMPARE(e.value[0], 4.5f);
    QVERIFY(e.finished);

    // Beyond the slider's travel, up to the hard range; the slider pins at its end.
    typeInto(field, "25");
    QCOMPARE(spy.count(), 2);
    QCOMPARE(editAt(spy, 1).value[0], 25.0f);
    auto* slider = child<QSlider>(&panel, "slider:growth.ring_width");
    QCOMPARE(slider->value(), slider->maximum());

    // Vector3 and integer fields.
    typeInto(child<QDoubleSpinBox>(&panel, "field:growth.pith_origin:1"), "7");
    e = editAt(spy, spy.count() - 1);
    QCOMPARE(e.index, indexOf("growth.pith_origin"));
    QCOMPARE(e.value[0], 12.0f);
    QCOMPARE(e.value[1], 7.0f);
    QCOMPARE(e.value[2], -75.0f);
    QVERIFY(e.finished);
    typeInto(child<QSpinBox>(&panel, "field:model.seed"), "1234");
    e = editAt(spy, spy.count() - 1);
    QCOMPARE(e.index, indexOf("model.seed"));
    QCOMPARE(e.value[0], 1234.0f);
    QVERIFY(e.finished);
    const int before = spy.count();
    QTest::mouseClick(child<QToolButton>(&panel, "random:model.seed"), Qt::LeftButton);
    QCOMPARE(spy.count(), before + 1);
    e = editAt(spy, before);
    QVERIFY(e.finished);
    QVERIFY(e.value[0] != 1234.0f);

    // A colour as hex.
    auto* hex = child<QLineEdit>(&panel, "hex:color.latewood");
    hex->setFocus();
    hex->selectAll();
    QTest::keyClicks(hex, "#336699");
    QTest::keyClick(hex, Qt::Key_Return);
    e = editAt(spy, spy.count() - 1);
    QCOMPARE(e.index, indexOf("color.latewood"));
    QVERIFY(e.finished);
    QCOMPARE(e.value[0], 0x33 / 255.0f);
    QCOMPARE(e.value[2], 0x99 / 255.0f);
  }

  void resetRestoresDefault() {
    ParameterPanel panel;
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    WoodParameters p;
    p.transition = 0.8f;
    p.rayColor = {0.1f, 0.2f, 0.3f};
    panel.setParameters(p);
    QSignalSpy spy(&panel, &ParameterPanel::parameterEdited);
    auto* reset = child<QToolButton>(&panel, "reset:rings.transition");
    QVERIFY(reset->isEnabled());
    QTest::mouseClick(reset, Qt::LeftButton);
    QCOMPARE(spy.count(), 1);
    Edit e = editAt(spy, 0);
    QCOMPARE(e.index, indexOf("rings.transition"));
    QCOMPARE(e.value[0], WoodParameters{}.transition);
    QVERIFY(e.finished);
    QVERIFY(!reset->isEnabled());
    QCOMPARE(float(child<QDoubleSpinBox>(&panel, "field:rings.transition")->value()),
             WoodParameters{}.transition);

    QTest::mouseClick(child<QToolButton>(&panel, "reset:rays.color"), Qt::LeftButton);
    QCOMPARE(spy.count(), 2);
    e = editAt(spy, 1);
    QCOMPARE(e.index, indexOf("rays.color"));
    QCOMPARE(glm::vec3(e.value[0], e.value[1], e.value[2]), WoodParameters{}.rayColor);
    QVERIFY(e.finished);
  }

  void colorPickerPreviewsThenCommits() {
    ParameterPanel panel;
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QSignalSpy spy(&panel, &ParameterPanel::parameterEdited);
    QTest::mouseClick(child<QWidget>(&panel, "swatch:color.earlywood"), Qt::LeftButton);
    auto* dialog = panel.findChild<QColorDialog*>("colorDialog:color.earlywood");
    QVERIFY(dialog);
    dialog->setCurrentColor(QColor(200, 100, 50));
    QVERIFY(spy.count() >= 1);
    QVERIFY(!editAt(spy, spy.count() - 1).finished);
    dialog->accept();
    const Edit e = editAt(spy, spy.count() - 1);
    QCOMPARE(e.index, indexOf("color.earlywood"));
    QVERIFY(e.finished);
    QCOMPARE(e.value[0], 200 / 255.0f);
    QCOMPARE(e.value[1], 100 / 255.0f);

    // Cancel after browsing restores the colour it had.
    spy.clear();
    QTest::mouseClick(child<QWidget>(&panel, "swatch:color.earlywood"), Qt::LeftButton);
    QTRY_VERIFY(panel.findChildren<QColorDialog*>().size() == 1);
    dialog = panel.findChild<QColorDialog*>("colorDialog:color.earlywood");
    dialog->setCurrentColor(QColor(10, 20, 30));
    dialog->reject();
    const Edit back = editAt(spy, spy.count() - 1);
    QVERIFY(back.finished);
    QCOMPARE(back.value[0], 200 / 255.0f);
  }

  void tintPickerDividesByTheReferenceWood() {
    ParameterPanel panel;
    panel.setSectionExpanded("faces", true);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QSignalSpy spy(&panel, &ParameterPanel::parameterEdited);
    auto* swatch = child<QWidget>(&panel, "swatch:faces.tint_a");
    swatch->setFocus();
    QTest::keyClick(swatch, Qt::Key_Space);
    auto* dialog = panel.findChild<QColorDialog*>("colorDialog:faces.tint_a");
    QVERIFY(dialog);
    // The swatch shows light wood (0.80, 0.62, 0.42) under the neutral tint; a redder wood gives R x1.1.
    QCOMPARE(dialog->currentColor().rgb(), QColor::fromRgbF(0.80f, 0.62f, 0.42f).rgb());
    dialog->setCurrentColor(QColor::fromRgbF(0.88f, 0.62f, 0.42f));
    dialog->accept();
    const Edit e = editAt(spy, spy.count() - 1);
    QCOMPARE(e.index, indexOf("faces.tint_a"));
    QVERIFY(e.finished);
    QCOMPARE(e.value[0], 1.1f);
    QCOMPARE(e.value[1], 1.0f);
    QCOMPARE(e.value[2], 1.0f);
    QCOMPARE(child<QDoubleSpinBox>(&panel, "field:faces.tint_a:0")->value(), 1.1);
  }

  void choosingAPresetEmitsPresetChosen() {
    QVERIFY(builtInPresets().size() >= 17);
    ParameterPanel panel;
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QComboBox* box = panel.presetBox();
    QCOMPARE(box->count(), static_cast<int>(builtInPresets().size()));
    QCOMPARE(box->currentIndex(), -1);  // "Choose a species…"
    QSignalSpy presets(&panel, &ParameterPanel::presetChosen);
    QSignalSpy edits(&panel, &ParameterPanel::parameterEdited);
    box->setFocus();
    QTest::keyClick(box, Qt::Key_Down);
    QCOMPARE(presets.count(), 1);
    QCOMPARE(presets.at(0).at(0).toString(), QString::fromStdString(builtInPresets()[0].id));
    QCOMPARE(edits.count(), 0);  // the lead applies the preset and calls setParameters
    QCOMPARE(panel.currentPreset(), QString::fromStdString(builtInPresets()[0].id));
    panel.setCurrentPreset("nara");
    QCOMPARE(box->currentText(), QStringLiteral("Japanese oak (nara)"));
    QCOMPARE(presets.count(), 1);
    QVERIFY(box->itemData(box->currentIndex(), Qt::ToolTipRole).toString().contains("Quercus crispula"));
    // Applying it (what the lead does) shows the species' values without emitting.
    const Preset* nara = builtInPreset("nara");
    QVERIFY(nara);
    panel.setParameters(nara->applyTo(panel.parameters()));
    QCOMPARE(edits.count(), 0);
    QCOMPARE(child<QDoubleSpinBox>(&panel, "field:rays.height")->value(), 8.0);
  }

  void filterHidesRows() {
    ParameterPanel panel;
    panel.resize(460, 700);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&panel));
    // Ctrl+F from anywhere in the panel puts the cursor in the filter.
    child<QSlider>(&panel, "slider:growth.ring_width")->setFocus();
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_F, Qt::ControlModifier);
    QVERIFY(panel.filterField()->hasFocus());
    QTest::keyClicks(panel.filterField(), "pore");
    const auto schema = parameterSchema();
    int shown = 0;
    for (std::size_t i = 0; i < schema.size(); ++i) {
      const bool pore = schema[i].id.rfind("pores.", 0) == 0;
      QCOMPARE(panel.rowMatchesFilter(static_cast<int>(i)), pore);
      QCOMPARE(panel.row(static_cast<int>(i))->isVisible(), pore);
      shown += pore;
    }
    // The pores group: spacing, two radii, taper, zone, thinning, two densities, length, darkness, hue.
    QCOMPARE(shown, 11);
    QVERIFY(!child<QToolButton>(&panel, "section:growth")->isVisible());
    QVERIFY(child<QToolButton>(&panel, "section:pores")->isVisible());
    saveShot(&panel, "parameter_panel_filtered.png");
    // By label, case-insensitive: "TINT" finds the face tints even in their collapsed section.
    panel.setFilterText("TINT");
    QVERIFY(panel.rowMatchesFilter(indexOf("faces.tint_a")));
    QVERIFY(panel.row(indexOf("faces.tint_a"))->isVisible());
    QVERIFY(!panel.rowMatchesFilter(indexOf("pores.length")));
    // Escape clears the filter.
    panel.filterField()->setFocus();
    QTest::keyClick(panel.filterField(), Qt::Key_Escape);
    QVERIFY(panel.filterText().isEmpty());
    for (int i = 0; i < panel.rowCount(); ++i) QVERIFY(panel.rowMatchesFilter(i));
    QVERIFY(!panel.row(indexOf("faces.tint_a"))->isVisible());  // collapsed again
  }

  void sectionsCollapse() {
    ParameterPanel panel;
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(panel.isSectionExpanded("pores"));
    QTest::mouseClick(child<QToolButton>(&panel, "section:pores"), Qt::LeftButton);
    QVERIFY(!panel.isSectionExpanded("pores"));
    QVERIFY(!panel.row(indexOf("pores.length"))->isVisible());
    panel.setSectionExpanded("pores", true);
    QVERIFY(panel.row(indexOf("pores.length"))->isVisibleTo(&panel));
  }

  void screenshots() {
    QWidget window;
    window.setWindowTitle("Parameters");
    auto* panel = new ParameterPanel(&window);
    auto* layout = new QVBoxLayout(&window);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(panel);
    WoodParameters p = builtInPreset("nara")->applyTo(WoodParameters{});
    p.poreRadiusEarly = 0.7f;  // beyond the slider: the handle rests at the end
    panel->setParameters(p);
    panel->setCurrentPreset("nara");
    panel->setSectionExpanded("faces", true);
    window.resize(460, 2000);  // tall enough to show every section at once
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    saveShot(&window, "parameter_panel_full.png");
    qInfo() << "panel minimum width" << panel->minimumSizeHint().width();
    QVERIFY(panel->minimumSizeHint().width() <= 460);
    window.resize(460, 760);
    panel->setSectionExpanded("faces", false);
    QTest::qWait(50);
    saveShot(&window, "parameter_panel.png");
    // The tooltip of a row, as a woodworker hovering the slider sees it.
    auto* slider = child<QSlider>(panel, "slider:growth.ring_width");
    QToolTip::showText(slider->mapToGlobal(QPoint(10, 10)), slider->toolTip(), slider);
    QWidget* tip = nullptr;
    QTRY_VERIFY((tip = [] {
      for (QWidget* w : QApplication::topLevelWidgets()) {
        if (w->inherits("QTipLabel") && w->isVisible()) return w;
      }
      return static_cast<QWidget*>(nullptr);
    }()));
    saveShot(tip, "parameter_tooltip.png");
    QToolTip::hideText();
    window.resize(panel->minimumSizeHint().width(), 600);  // as narrow as a dock may make it
    QTest::qWait(50);
    saveShot(&window, "parameter_panel_narrow.png");
  }
};

class CutPlaneControlsTest : public QObject {
  Q_OBJECT

 private slots:
  void setSettingDoesNotEmit() {
    CutPlaneControls controls;
    QSignalSpy spy(&controls, &CutPlaneControls::settingEdited);
    controls.setSetting({5.0f, 30.0f, 45.0f});
    controls.setSetting({-2.0f, 270.0f, -10.0f});
    QCOMPARE(spy.count(), 0);
    QCOMPARE(controls.setting().azimuthDeg, -90.0f);  // wrapped
    QCOMPARE(child<QDoubleSpinBox>(&controls, "field:azimuth")->value(), -90.0);
    QCOMPARE(child<QDoubleSpinBox>(&controls, "field:offset")->value(), -2.0);
  }

  void blockSetsOffsetRange() {
    CutPlaneControls controls;
    QVERIFY(std::abs(controls.offsetLimitMm() - 0.5f * std::sqrt(3.0f) * 40.0f) < 1e-3f);
    controls.setBlock(Block({100, 20, 20}));
    QVERIFY(std::abs(controls.offsetLimitMm() - 0.5f * std::sqrt(10800.0f)) < 1e-3f);
    QVERIFY(std::abs(child<QDoubleSpinBox>(&controls, "field:offset")->maximum() - 51.96) < 0.06);
    QVERIFY(std::abs(child<QDoubleSpinBox>(&controls, "field:offset")->minimum() + 51.96) < 0.06);
  }

  void snappingEmitsSnappedValues() {
    CutPlaneControls controls;
    controls.setCutEnabled(true);
    controls.setSetting({3.0f, 37.0f, 8.0f});
    controls.show();
    QVERIFY(QTest::qWaitForWindowExposed(&controls));
    QSignalSpy spy(&controls, &CutPlaneControls::settingEdited);
    // Turning snapping on snaps the current plane.
    clickIndicator(child<QCheckBox>(&controls, "snapAngles"));
    QVERIFY(controls.snapping());
    QCOMPARE(spy.count(), 1);
    CutPlaneSetting s = settingAt(spy, 0);
    QCOMPARE(s.azimuthDeg, 30.0f);
    QCOMPARE(s.elevationDeg, 15.0f);
    QCOMPARE(s.offsetMm, 3.0f);  // offsets are not snapped
    QVERIFY(spy.at(0).at(1).toBool());
    // A typed angle is snapped.
    typeInto(child<QDoubleSpinBox>(&controls, "field:elevation"), "52");
    s = settingAt(spy, spy.count() - 1);
    QCOMPARE(s.elevationDeg, 45.0f);
    QVERIFY(spy.at(spy.count() - 1).at(1).toBool());
    QCOMPARE(child<QDoubleSpinBox>(&controls, "field:elevation")->value(), 45.0);
    // Arrow keys on a slider step by 15°.
    auto* slider = child<QSlider>(&controls, "slider:azimuth");
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_Right);
    s = settingAt(spy, spy.count() - 1);
    QCOMPARE(s.azimuthDeg, 45.0f);
    QVERIFY(spy.at(spy.count() - 1).at(1).toBool());
    // A drag only ever emits multiples of 15°, then finishes on release.
    spy.clear();
    dragSlider(child<QSlider>(&controls, "slider:elevation"), 8, -7);
    QVERIFY(spy.count() >= 2);
    for (int i = 0; i < spy.count(); ++i) {
      const float e = settingAt(spy, i).elevationDeg;
      QCOMPARE(std::fmod(std::abs(e), 15.0f), 0.0f);
      QCOMPARE(spy.at(i).at(1).toBool(), i == spy.count() - 1);
    }
  }

  void dragWithoutSnapping() {
    CutPlaneControls controls;
    controls.setCutEnabled(true);
    controls.show();
    QVERIFY(QTest::qWaitForWindowExposed(&controls));
    QSignalSpy spy(&controls, &CutPlaneControls::settingEdited);
    dragSlider(child<QSlider>(&controls, "slider:offset"), 4, 5);
    QVERIFY(spy.count() >= 2);
    QVERIFY(!spy.at(0).at(1).toBool());
    QVERIFY(spy.at(spy.count() - 1).at(1).toBool());
    QVERIFY(controls.setting().offsetMm > 0.0f);
  }

  void principalPlanes() {
    CutPlaneControls controls;
    controls.setCutEnabled(true);
    controls.setSetting({7.0f, 33.0f, 21.0f});
    controls.show();
    QVERIFY(QTest::qWaitForWindowExposed(&controls));
    QSignalSpy spy(&controls, &CutPlaneControls::settingEdited);
    QTest::mouseClick(child<QPushButton>(&controls, "planeBD"), Qt::LeftButton);
    QCOMPARE(spy.count(), 1);
    CutPlaneSetting s = settingAt(spy, 0);
    QCOMPARE(s.elevationDeg, 90.0f);
    QCOMPARE(s.offsetMm, 0.0f);
    QVERIFY(spy.at(0).at(1).toBool());
    QVERIFY(glm::length(s.normal() - glm::vec3(0, 1, 0)) < 1e-5f);
    QVERIFY(controls.findChild<QLabel*>("cutDescription")->text().contains("end grain"));

    QTest::mouseClick(child<QPushButton>(&controls, "planeAF"), Qt::LeftButton);
    s = settingAt(spy, 1);
    QCOMPARE(s.elevationDeg, 0.0f);
    QVERIFY(glm::length(s.normal() - glm::vec3(0, 0, 1)) < 1e-5f);  // towards face A
    QVERIFY(controls.findChild<QLabel*>("cutDescription")->text().contains("long grain"));

    QTest::mouseClick(child<QPushButton>(&controls, "planeCE"), Qt::LeftButton);
    s = settingAt(spy, 2);
    QCOMPARE(s.elevationDeg, 0.0f);
    QVERIFY(glm::length(s.normal() - glm::vec3(-1, 0, 0)) < 1e-5f);  // towards face C
    QCOMPARE(spy.count(), 3);
  }

  void azimuthWraps() {
    CutPlaneControls controls;
    controls.setCutEnabled(true);
    controls.setSetting({0.0f, 179.0f, 0.0f});
    controls.show();
    QVERIFY(QTest::qWaitForWindowExposed(&controls));
    QSignalSpy spy(&controls, &CutPlaneControls::settingEdited);
    auto* field = child<QDoubleSpinBox>(&controls, "field:azimuth");
    field->setFocus();
    QTest::keyClick(field, Qt::Key_Up);
    QTest::keyClick(field, Qt::Key_Up);
    QTest::keyClick(field, Qt::Key_Up);
    QVERIFY(spy.count() >= 2);
    const float last = settingAt(spy, spy.count() - 1).azimuthDeg;
    QCOMPARE(last, -179.0f);  // 179 -> 180 (= -180) -> -179
  }

  void showAndSideSignals() {
    CutPlaneControls controls;
    controls.show();
    QVERIFY(QTest::qWaitForWindowExposed(&controls));
    QSignalSpy enabled(&controls, &CutPlaneControls::cutEnabledChanged);
    QSignalSpy side(&controls, &CutPlaneControls::cutSideChanged);
    QVERIFY(!child<QSlider>(&controls, "slider:offset")->isEnabled());  // no cut, nothing to set
    clickIndicator(child<QCheckBox>(&controls, "showCut"));
    QCOMPARE(enabled.count(), 1);
    QVERIFY(enabled.at(0).at(0).toBool());
    QVERIFY(child<QSlider>(&controls, "slider:offset")->isEnabled());
    clickIndicator(child<QRadioButton>(&controls, "ghostCutAway"));
    QVERIFY(controls.ghost());
    QVERIFY(side.count() >= 1);
    QVERIFY(side.at(side.count() - 1).at(0).toBool());
    controls.setGhost(false);
    controls.setCutEnabled(false);
    QCOMPARE(enabled.count(), 1);  // setters do not emit
    QVERIFY(!controls.ghost());
  }

  void screenshot() {
    CutPlaneControls controls;
    controls.setCutEnabled(true);
    controls.setSetting({4.5f, 30.0f, 60.0f});
    controls.setSnapping(true);
    controls.resize(380, controls.sizeHint().height());
    controls.show();
    QVERIFY(QTest::qWaitForWindowExposed(&controls));
    saveShot(&controls, "cut_plane_controls.png");
  }
};

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  int status = 0;
  {
    ParameterPanelTest test;
    status |= QTest::qExec(&test, argc, argv);
  }
  if (!kerf::testing::timingChecks()) {  // the `timing` run names a function of ParameterPanelTest only
    CutPlaneControlsTest test;
    status |= QTest::qExec(&test, argc, argv);
  }
  return status;
}

#include "test_parameter_panel.moc"
