#pragma once
// Numeric controls of the cut plane (kerf::CutPlaneSetting): show/hide the cut, the saw's offset from
// the block centre, the plane's azimuth and elevation (each a slider with a number field), snapping of
// both angles to 15°, buttons for the three principal planes, and whether the cut-away part is hidden or
// shown as a ghost. A line under the controls says in wood terms what the cut shows (end grain, long
// grain, slanted).
//
// Like ParameterPanel, the controls report edits and never own the document: settingEdited(setting,
// finished) with finished = false for each intermediate value of a slider drag and true on release,
// keyboard steps, committed numbers, snapping turned on and principal-plane buttons. While the cut is
// off, the plane controls are disabled.
#include <QWidget>

#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"

class QButtonGroup;
class QCheckBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QPushButton;
class QRadioButton;
class QSlider;

namespace kerf {

class CutPlaneControls : public QWidget {
  Q_OBJECT

 public:
  static constexpr float kSnapStepDeg = 15.0f;

  explicit CutPlaneControls(QWidget* parent = nullptr);

  // Shows `setting` without emitting (the azimuth wrapped into -180..180, the offset as given even if
  // the field has to clamp it for display).
  void setSetting(const CutPlaneSetting& setting);
  CutPlaneSetting setting() const { return setting_; }
  // The offset range becomes ± half the block's diagonal (every plane that touches the block).
  void setBlock(const Block& block);
  float offsetLimitMm() const { return offsetLimit_; }

  // These setters do not emit.
  void setCutEnabled(bool enabled);
  bool cutEnabled() const;
  void setGhost(bool ghost);
  bool ghost() const;
  void setSnapping(bool on);
  bool snapping() const;

  // The principal planes through the block centre (normal towards A, B or C respectively).
  static CutPlaneSetting planeParallelToAF();
  static CutPlaneSetting planeParallelToBD();  // the cross-section: end grain
  static CutPlaneSetting planeParallelToCE();
  // One line in wood terms about what a cut with these angles shows.
  static QString describe(const CutPlaneSetting& setting);

 signals:
  void settingEdited(kerf::CutPlaneSetting setting, bool finished);
  void cutEnabledChanged(bool enabled);
  void cutSideChanged(bool ghost);

 private:
  struct Axis {
    QSlider* slider = nullptr;
    QDoubleSpinBox* field = nullptr;
    float scale = 10.0f;  // slider units per mm or degree
    bool dragEmitted = false;
  };
  enum AxisId { Offset = 0, Azimuth = 1, Elevation = 2 };

  void buildAxis(AxisId id, QGridLayout* grid, int row, const QString& label, const QString& tip);
  void edit(AxisId id, float value, bool finished);
  void emitSetting(CutPlaneSetting setting, bool finished);
  void showSetting();
  void updateEnabled();

  CutPlaneSetting setting_;
  float offsetLimit_ = 0.0f;
  Axis axes_[3];
  QCheckBox* show_ = nullptr;
  QCheckBox* snap_ = nullptr;
  QPushButton* principal_[3] = {};
  QRadioButton* hide_ = nullptr;
  QRadioButton* ghost_ = nullptr;
  QLabel* description_ = nullptr;
  QWidget* planeWidgets_ = nullptr;
};

}  // namespace kerf
