#include "cut_plane_controls.hpp"

#include <QButtonGroup>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace kerf {
namespace {

// Into -180..180. Both ends are kept as they are (the same plane), so the wrapping field can step from
// 180 to -180 and on to -179.
float wrapDegrees(float deg) {
  return (deg >= -180.0f && deg <= 180.0f) ? deg : std::remainder(deg, 360.0f);
}

}  // namespace

CutPlaneSetting CutPlaneControls::planeParallelToAF() {
  return {0.0f, -90.0f, 0.0f};  // normal +z, towards A
}
CutPlaneSetting CutPlaneControls::planeParallelToBD() {
  return {0.0f, 0.0f, 90.0f};  // normal +y, towards B
}
CutPlaneSetting CutPlaneControls::planeParallelToCE() {
  return {0.0f, 180.0f, 0.0f};  // normal -x, towards C
}

QString CutPlaneControls::describe(const CutPlaneSetting& setting) {
  const float e = std::abs(setting.elevationDeg);
  if (e >= 89.5f) return tr("Cross-section: end grain, the rings as on the end of a log.");
  if (e >= 75.0f) {
    return tr("Nearly a cross-section: end grain, %1° off square to the B–D axis.")
        .arg(std::round(90.0f - e), 0, 'f', 0);
  }
  if (e <= 15.0f) {
    return tr(
        "Lengthwise cut: long grain. Quartersawn where it runs radially through the pith (straight stripes, "
        "ray fleck), flat-sawn where it passes beside the pith (arches).");
  }
  return tr("Slanted cut at %1° to the grain: the rings show as stretched ovals, as on a bias-sawn board.")
      .arg(std::round(e), 0, 'f', 0);
}

CutPlaneControls::CutPlaneControls(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("cutPlaneControls"));
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(6, 6, 6, 6);
  outer->setSpacing(6);

  show_ = new QCheckBox(tr("Show cut"), this);
  show_->setObjectName(QStringLiteral("showCut"));
  show_->setToolTip(tr("Saw the block along the cut plane and show the cut face."));
  outer->addWidget(show_);
  connect(show_, &QCheckBox::toggled, this, [this](bool on) {
    updateEnabled();
    emit cutEnabledChanged(on);
  });

  planeWidgets_ = new QWidget(this);
  auto* planeLayout = new QVBoxLayout(planeWidgets_);
  planeLayout->setContentsMargins(0, 0, 0, 0);
  planeLayout->setSpacing(6);
  outer->addWidget(planeWidgets_);

  auto* grid = new QGridLayout;
  grid->setHorizontalSpacing(6);
  grid->setVerticalSpacing(4);
  grid->setColumnStretch(1, 1);
  buildAxis(Offset, grid, 0, tr("Offset"),
            tr("Where the saw cuts: distance of the plane from the block centre, along the plane's normal. "
               "0 cuts through the middle of the block."));
  buildAxis(Azimuth, grid, 1, tr("Azimuth"),
            tr("Which way the cut faces, turning around the block's B–D axis (along which the pith normally "
               "runs): 0° faces E, -90° faces A, 90° faces F, ±180° faces C. Wraps around."));
  buildAxis(
      Elevation, grid, 2, tr("Elevation"),
      tr("How far the cut tips towards the end of the block: 0° is a lengthwise cut along the grain (long "
         "grain), 90° a cross-section square to the trunk like faces B and D (end grain); in between the "
         "cut runs slanted across the grain."));
  planeLayout->addLayout(grid);

  snap_ = new QCheckBox(tr("Snap to 15°"), planeWidgets_);
  snap_->setObjectName(QStringLiteral("snapAngles"));
  snap_->setToolTip(
      tr("Round both angles to multiples of 15° (0°, 15°, 30°, 45°...), like the detents of a "
         "mitre gauge."));
  planeLayout->addWidget(snap_);
  connect(snap_, &QCheckBox::toggled, this, [this](bool on) {
    for (AxisId id : {Azimuth, Elevation}) {
      axes_[id].slider->setSingleStep(on ? static_cast<int>(kSnapStepDeg * axes_[id].scale)
                                         : static_cast<int>(axes_[id].scale));
      axes_[id].field->setSingleStep(on ? kSnapStepDeg : 1.0);
    }
    if (on) {
      CutPlaneSetting s = setting_.snapped(kSnapStepDeg);
      s.azimuthDeg = wrapDegrees(s.azimuthDeg);
      if (!(s == setting_)) emitSetting(s, true);
    }
  });

  // End grain above the two lengthwise cuts: the column stays narrow, so the cut panel beside it is wide.
  auto* planes = new QGridLayout;
  planes->setSpacing(4);
  const QString lengthwise = tr(
      "Long grain, quartersawn or flat-sawn depending on its angle to the rings: quartersawn (straight "
      "stripes, "
      "ray fleck) where the plane runs radially, through the pith; flat-sawn (arches, 'cathedrals') where it "
      "runs along the rings, beside the pith.");
  const struct {
    const char* name;
    QString text;
    QString tip;
    CutPlaneSetting setting;
  } kPlanes[] = {
      {"planeBD", tr("End grain (B/D)"),
       tr("Cross-section through the block centre, parallel to faces B and D, square to the pith direction: "
          "end "
          "grain, where you count the rings."),
       planeParallelToBD()},
      {"planeAF", tr("Along A/F"),
       tr("Lengthwise cut through the block centre, parallel to faces A and F. ") + lengthwise,
       planeParallelToAF()},
      {"planeCE", tr("Along C/E"),
       tr("Lengthwise cut through the block centre, parallel to faces C and E. ") + lengthwise,
       planeParallelToCE()},
  };
  for (int i = 0; i < 3; ++i) {
    principal_[i] = new QPushButton(kPlanes[i].text, planeWidgets_);
    principal_[i]->setObjectName(QLatin1String(kPlanes[i].name));
    principal_[i]->setToolTip(kPlanes[i].tip);
    principal_[i]->setAutoDefault(false);
    if (i == 0)
      planes->addWidget(principal_[i], 0, 0, 1, 2);
    else
      planes->addWidget(principal_[i], 1, i - 1);
    const CutPlaneSetting target = kPlanes[i].setting;
    connect(principal_[i], &QPushButton::clicked, this, [this, target] { emitSetting(target, true); });
  }
  planeLayout->addLayout(planes);

  auto* side = new QHBoxLayout;
  side->setSpacing(12);
  auto* sideLabel = new QLabel(tr("Cut-away part:"), planeWidgets_);
  hide_ = new QRadioButton(tr("Hide"), planeWidgets_);
  hide_->setObjectName(QStringLiteral("hideCutAway"));
  hide_->setToolTip(tr("Remove the wood on the cut-away side of the plane, as if it had been sawn off."));
  ghost_ = new QRadioButton(tr("Ghost"), planeWidgets_);
  ghost_->setObjectName(QStringLiteral("ghostCutAway"));
  ghost_->setToolTip(
      tr("Show the cut-away side as a faint see-through ghost, so the block's outline stays "
         "visible."));
  hide_->setChecked(true);
  auto* group = new QButtonGroup(this);
  group->addButton(hide_);
  group->addButton(ghost_);
  side->addWidget(sideLabel);
  side->addWidget(hide_);
  side->addWidget(ghost_);
  side->addStretch(1);
  planeLayout->addLayout(side);
  connect(ghost_, &QRadioButton::toggled, this, [this](bool on) { emit cutSideChanged(on); });

  description_ = new QLabel(planeWidgets_);
  description_->setObjectName(QStringLiteral("cutDescription"));
  description_->setWordWrap(true);
  description_->setForegroundRole(QPalette::PlaceholderText);
  planeLayout->addWidget(description_);
  outer->addStretch(1);

  setBlock(Block());
  showSetting();
  updateEnabled();
}

void CutPlaneControls::buildAxis(AxisId id, QGridLayout* grid, int row, const QString& label,
                                 const QString& tip) {
  static const char* kNames[] = {"offset", "azimuth", "elevation"};
  Axis& axis = axes_[id];
  auto* text = new QLabel(label, planeWidgets_);
  text->setToolTip(tip);
  axis.slider = new QSlider(Qt::Horizontal, planeWidgets_);
  axis.slider->setObjectName(QStringLiteral("slider:") + QLatin1String(kNames[id]));
  axis.slider->setToolTip(tip);
  axis.slider->setFocusPolicy(Qt::StrongFocus);
  axis.field = new QDoubleSpinBox(planeWidgets_);
  axis.field->setObjectName(QStringLiteral("field:") + QLatin1String(kNames[id]));
  axis.field->setToolTip(tip);
  axis.field->setDecimals(1);
  axis.field->setKeyboardTracking(false);
  axis.field->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  axis.field->setAccelerated(true);
  axis.field->setSuffix(id == Offset ? QStringLiteral(" mm") : QStringLiteral("°"));
  axis.field->setMinimumWidth(axis.field->fontMetrics().horizontalAdvance(QStringLiteral("-000.0 mm")) + 30);
  text->setBuddy(axis.field);
  if (id == Azimuth) {
    axis.field->setRange(-180.0, 180.0);
    axis.field->setWrapping(true);
    axis.slider->setRange(-1800, 1800);
  } else if (id == Elevation) {
    axis.field->setRange(-90.0, 90.0);
    axis.slider->setRange(-900, 900);
  }
  axis.slider->setSingleStep(static_cast<int>(axis.scale));
  axis.slider->setPageStep(static_cast<int>(15 * axis.scale));
  axis.field->setSingleStep(1.0);
  grid->addWidget(text, row, 0);
  grid->addWidget(axis.slider, row, 1);
  grid->addWidget(axis.field, row, 2);

  connect(axis.slider, &QSlider::valueChanged, this, [this, id](int position) {
    Axis& a = axes_[id];
    const bool dragging = a.slider->isSliderDown();
    if (dragging) a.dragEmitted = true;
    edit(id, position / a.scale, !dragging);
  });
  connect(axis.slider, &QSlider::sliderPressed, this, [this, id] { axes_[id].dragEmitted = false; });
  connect(axis.slider, &QSlider::sliderReleased, this, [this, id] {
    if (!axes_[id].dragEmitted) return;
    axes_[id].dragEmitted = false;
    emitSetting(setting_, true);
  });
  connect(axis.field, &QDoubleSpinBox::valueChanged, this,
          [this, id](double value) { edit(id, static_cast<float>(value), true); });
}

void CutPlaneControls::edit(AxisId id, float value, bool finished) {
  CutPlaneSetting s = setting_;
  if (id == Offset) s.offsetMm = std::clamp(value, -offsetLimit_, offsetLimit_);
  if (id == Azimuth) s.azimuthDeg = value;
  if (id == Elevation) s.elevationDeg = std::clamp(value, -90.0f, 90.0f);
  if (snapping()) s = s.snapped(kSnapStepDeg);
  s.azimuthDeg = wrapDegrees(s.azimuthDeg);
  if (s == setting_) {
    // Nothing changed (e.g. a snapped drag that has not reached the next step): keep the handle and the
    // field on the current value.
    showSetting();
    return;
  }
  emitSetting(s, finished);
}

void CutPlaneControls::emitSetting(CutPlaneSetting setting, bool finished) {
  setting_ = setting;
  showSetting();
  emit settingEdited(setting_, finished);
}

void CutPlaneControls::setSetting(const CutPlaneSetting& setting) {
  setting_ = setting;
  setting_.azimuthDeg = wrapDegrees(setting_.azimuthDeg);
  showSetting();
}

void CutPlaneControls::showSetting() {
  const float values[3] = {setting_.offsetMm, setting_.azimuthDeg, setting_.elevationDeg};
  for (int i = 0; i < 3; ++i) {
    Axis& axis = axes_[i];
    {
      const QSignalBlocker block(axis.slider);
      axis.slider->setValue(static_cast<int>(std::lround(values[i] * axis.scale)));
    }
    const QSignalBlocker block(axis.field);
    axis.field->setValue(values[i]);
  }
  description_->setText(describe(setting_));
}

void CutPlaneControls::setBlock(const Block& block) {
  offsetLimit_ = 0.5f * glm::length(block.size());
  Axis& axis = axes_[Offset];
  const int limit = static_cast<int>(std::ceil(offsetLimit_ * axis.scale));
  {
    const QSignalBlocker block1(axis.slider);
    axis.slider->setRange(-limit, limit);
  }
  {
    const QSignalBlocker block2(axis.field);
    axis.field->setRange(-offsetLimit_, offsetLimit_);
  }
  showSetting();
}

void CutPlaneControls::setCutEnabled(bool enabled) {
  const QSignalBlocker block(show_);
  show_->setChecked(enabled);
  updateEnabled();
}

bool CutPlaneControls::cutEnabled() const {
  return show_->isChecked();
}

void CutPlaneControls::setGhost(bool ghost) {
  const QSignalBlocker block1(hide_);
  const QSignalBlocker block2(ghost_);
  (ghost ? ghost_ : hide_)->setChecked(true);
}

bool CutPlaneControls::ghost() const {
  return ghost_->isChecked();
}

void CutPlaneControls::setSnapping(bool on) {
  const QSignalBlocker block(snap_);
  snap_->setChecked(on);
  for (AxisId id : {Azimuth, Elevation}) {
    axes_[id].slider->setSingleStep(on ? static_cast<int>(kSnapStepDeg * axes_[id].scale)
                                       : static_cast<int>(axes_[id].scale));
    axes_[id].field->setSingleStep(on ? kSnapStepDeg : 1.0);
  }
}

bool CutPlaneControls::snapping() const {
  return snap_->isChecked();
}

void CutPlaneControls::updateEnabled() {
  planeWidgets_->setEnabled(show_->isChecked());
}

}  // namespace kerf
