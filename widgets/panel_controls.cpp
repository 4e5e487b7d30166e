#include "panel_controls.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSpinBox>

namespace kerf {
namespace {

QDoubleSpinBox* millimetres(double value, double max, QWidget* parent) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(0.5, max);
  box->setDecimals(1);
  box->setSuffix(" mm");
  box->setValue(value);
  return box;
}

}  // namespace

PanelControls::PanelControls(QWidget* parent) : QWidget(parent) {
  auto* form = new QFormLayout(this);
  type_ = new QComboBox(this);
  type_->addItem(tr("CLT (cross-laminated timber)"), static_cast<int>(PanelType::Clt));
  type_->addItem(tr("Plywood"), static_cast<int>(PanelType::Plywood));
  type_->addItem(tr("Rotary-cut veneer"), static_cast<int>(PanelType::Veneer));
  type_->setToolTip(tr("A product made of many pieces of this log (Larsson et al. 2022 Sec. 5)"));
  form->addRow(tr("Panel"), type_);
  face_ = new QComboBox(this);
  for (FaceId id : kAllFaces) face_->addItem(QString(QChar(faceLetter(id))));
  face_->setToolTip(tr("The face shown: A is the top, C..F the edges where the layers show"));
  form->addRow(tr("Face"), face_);
  auto* size = new QHBoxLayout;
  width_ = millimetres(600, 5000, this);
  length_ = millimetres(600, 5000, this);
  thickness_ = millimetres(90, 500, this);
  width_->setToolTip(tr("Width"));
  length_->setToolTip(tr("Length (the outer layers' grain)"));
  thickness_->setToolTip(tr("Thickness"));
  for (QDoubleSpinBox* box : {width_, length_, thickness_}) size->addWidget(box);
  form->addRow(tr("Size"), size);
  layers_ = new QSpinBox(this);
  layers_->setRange(1, 64);
  layers_->setValue(3);
  layers_->setToolTip(tr("CLT: layers of lamellas; plywood: plies"));
  form->addRow(tr("Layers"), layers_);
  lamellaWidth_ = millimetres(120, 1000, this);
  form->addRow(tr("Lamella width"), lamellaWidth_);
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 1000000);
  seed_->setValue(1);
  seed_->setToolTip(tr("Where in the log the lamellas are cut: each seed another panel"));
  form->addRow(tr("Seed"), seed_);
  veneerThickness_ = millimetres(1.5, 20, this);
  veneerThickness_->setMinimum(0.1);
  veneerThickness_->setToolTip(tr("The veneer's thickness: how far the lathe's knife moves in per turn"));
  form->addRow(tr("Veneer thickness"), veneerThickness_);
  auto* sheet = new QHBoxLayout;
  sheetLength_ = millimetres(1200, 100000, this);
  sheetWidth_ = millimetres(600, 5000, this);
  sheetLength_->setToolTip(tr("Length along the peel"));
  sheetWidth_->setToolTip(tr("Width, up the log"));
  sheet->addWidget(sheetLength_);
  sheet->addWidget(sheetWidth_);
  form->addRow(tr("Veneer sheet"), sheet);
  show_ = new QPushButton(tr("Show Panel"), this);
  show_->setToolTip(tr("Render the panel from this log in the background and show it in the Panel view"));
  form->addRow(show_);
  connect(type_, &QComboBox::currentIndexChanged, this,
          [this] { setType(static_cast<PanelType>(type_->currentData().toInt())); });
  connect(show_, &QPushButton::clicked, this, [this] { emit panelRequested(options()); });
  typeChanged();
}

void PanelControls::setType(PanelType type) {
  const int index = type_->findData(static_cast<int>(type));
  if (index != type_->currentIndex()) {
    type_->setCurrentIndex(index);  // comes back here through currentIndexChanged
    return;
  }
  if (type == PanelType::Plywood) thickness_->setValue(12), layers_->setValue(5);
  if (type == PanelType::Clt) thickness_->setValue(90), layers_->setValue(3);
  typeChanged();
}

void PanelControls::typeChanged() {
  const auto type = static_cast<PanelType>(type_->currentData().toInt());
  const bool layered = type != PanelType::Veneer;
  for (QWidget* w : std::initializer_list<QWidget*>{face_, width_, length_, thickness_, layers_})
    w->setEnabled(layered);
  lamellaWidth_->setEnabled(type == PanelType::Clt);
  seed_->setEnabled(type == PanelType::Clt);
  veneerThickness_->setEnabled(!layered);
  sheetLength_->setEnabled(!layered);
  sheetWidth_->setEnabled(!layered);
}

PanelOptions PanelControls::options() const {
  PanelOptions o;
  o.type = static_cast<PanelType>(type_->currentData().toInt());
  o.face = kAllFaces[face_->currentIndex()];
  o.sizeMm = glm::vec3(width_->value(), length_->value(), thickness_->value());
  o.layers = layers_->value();
  o.lamellaWidthMm = static_cast<float>(lamellaWidth_->value());
  o.seed = static_cast<std::uint32_t>(seed_->value());
  o.veneerThicknessMm = static_cast<float>(veneerThickness_->value());
  o.sheetMm = glm::vec2(sheetLength_->value(), sheetWidth_->value());
  return o;
}

}  // namespace kerf
