#pragma once
// The choice of a wood product made from the open log (render/panel_render.hpp): CLT, rotary-cut veneer
// or plywood, its size, layers, seed (CLT), veneer thickness and sheet, and the face shown. "Show Panel"
// emits panelRequested with the options; the fields that do not apply to the chosen type are disabled.
#include <QWidget>

#include "render/panel_render.hpp"

class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QSpinBox;

namespace kerf {

class PanelControls : public QWidget {
  Q_OBJECT

 public:
  explicit PanelControls(QWidget* parent = nullptr);

  PanelOptions options() const;
  void setType(PanelType type);  // also resets the size to that type's default
  QPushButton* showButton() const { return show_; }

 signals:
  void panelRequested(kerf::PanelOptions options);

 private:
  void typeChanged();

  QComboBox* type_ = nullptr;
  QComboBox* face_ = nullptr;
  QDoubleSpinBox *width_ = nullptr, *length_ = nullptr, *thickness_ = nullptr;
  QSpinBox* layers_ = nullptr;
  QSpinBox* seed_ = nullptr;
  QDoubleSpinBox* lamellaWidth_ = nullptr;
  QDoubleSpinBox* veneerThickness_ = nullptr;
  QDoubleSpinBox *sheetLength_ = nullptr, *sheetWidth_ = nullptr;
  QPushButton* show_ = nullptr;
};

}  // namespace kerf
