#include "part_export_dialog.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <initializer_list>

#include "export_format_box.hpp"
#include "mesh/mesh_loader.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

QDoubleSpinBox* spinBox(double min, double max, int decimals, double step, const QString& suffix,
                        const QString& tip) {
  auto* box = new QDoubleSpinBox;
  box->setRange(min, max);
  box->setDecimals(decimals);
  box->setSingleStep(step);
  box->setSuffix(suffix);
  box->setToolTip(tip);
  return box;
}

QHBoxLayout* rowOf(std::initializer_list<QWidget*> boxes) {
  auto* row = new QHBoxLayout;
  for (QWidget* b : boxes) row->addWidget(b);
  return row;
}

}  // namespace

PartExportDialog::PartExportDialog(const Block& block, const QString& folder, QWidget* parent)
    : QDialog(parent), block_(block) {
  setWindowTitle(tr("Export Part"));
  auto* form = new QFormLayout;

  meshPath_ = new QLineEdit;
  meshPath_->setToolTip(tr("The part to mill: OBJ, STL or PLY, in millimetres"));
  auto* meshBrowse = new QPushButton(tr("Browse…"));
  auto* meshRow = new QHBoxLayout;
  meshRow->addWidget(meshPath_, 1);
  meshRow->addWidget(meshBrowse);
  form->addRow(tr("Mesh:"), meshRow);
  meshInfo_ = new QLabel;
  form->addRow(meshInfo_);
  connect(meshBrowse, &QPushButton::clicked, this, &PartExportDialog::browseMesh);
  connect(meshPath_, &QLineEdit::editingFinished, this, [this] { setMeshPath(meshPath_->text()); });

  const QString axes[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    translation_[i] = spinBox(-1000, 1000, 2, 0.5, tr(" mm"),
                              tr("Where the part goes along the block's %1 axis (block mm, 0 = the block "
                                 "centre; docs/coordinates.md)")
                                  .arg(axes[i]));
    rotation_[i] = spinBox(-360, 360, 1, 5, tr("°"),
                           tr("Turn about the block's %1 axis (x first, then y, then z)").arg(axes[i]));
    rotation_[i]->setWrapping(true);
  }
  form->addRow(tr("Position x, y, z:"), rowOf({translation_[0], translation_[1], translation_[2]}));
  form->addRow(tr("Rotation x, y, z:"), rowOf({rotation_[0], rotation_[1], rotation_[2]}));
  scale_ = spinBox(0.001, 1000, 3, 0.05, QString(), tr("Uniform scale of the mesh (1 = its file's mm)"));
  scale_->setValue(1.0);
  form->addRow(tr("Scale:"), scale_);
  centre_ = new QCheckBox(tr("Centre in block"));
  centre_->setToolTip(
      tr("Centre the turned part's bounding box at the position (0, 0, 0 = the block centre) "
         "instead of the mesh file's origin"));
  centre_->setChecked(true);
  form->addRow(QString(), centre_);

  resolution_ = new QSpinBox;
  resolution_->setRange(16, 16384);
  resolution_->setValue(1024);
  resolution_->setSingleStep(256);
  resolution_->setSuffix(tr(" px"));
  resolution_->setToolTip(tr("Side of the square baked texture; the dialog's result says the texels per mm"));
  form->addRow(tr("Texture:"), resolution_);

  format_ = new QComboBox;
  addExportFormats(format_, ExportKind::Part);
  format_->setToolTip(tr("OBJ for CAM and most 3D programs; GLB for viewers, the web and Blender (metres)"));
  form->addRow(tr("Format:"), format_);
  path_ = new QLineEdit(QDir(folder).filePath("part.obj"));
  auto* outBrowse = new QPushButton(tr("Browse…"));
  auto* outRow = new QHBoxLayout;
  outRow->addWidget(path_, 1);
  outRow->addWidget(outBrowse);
  form->addRow(tr("File:"), outRow);
  connect(outBrowse, &QPushButton::clicked, this, &PartExportDialog::browseOut);
  connect(format_, &QComboBox::currentIndexChanged, this, &PartExportDialog::formatChanged);
  connect(path_, &QLineEdit::textChanged, this, [this] { selectExportFormatOf(format_, path_->text()); });

  fit_ = new QLabel;
  fit_->setWordWrap(true);
  form->addRow(fit_);
  problem_ = new QLabel;
  problem_->setStyleSheet("color: #c0392b");
  problem_->setWordWrap(true);
  problem_->hide();
  form->addRow(problem_);

  for (QDoubleSpinBox* box :
       {translation_[0], translation_[1], translation_[2], rotation_[0], rotation_[1], rotation_[2], scale_})
    connect(box, &QDoubleSpinBox::valueChanged, this, &PartExportDialog::updatePart);
  connect(centre_, &QCheckBox::toggled, this, &PartExportDialog::updatePart);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
  connect(buttons, &QDialogButtonBox::accepted, this, &PartExportDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &PartExportDialog::reject);
  connect(this, &QDialog::finished, this, [this] { emit partChanged(nullptr); });
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);
  updatePart();
}

void PartExportDialog::setMeshPath(const QString& path) {
  {
    const QSignalBlocker block(meshPath_);
    meshPath_->setText(path);
  }
  mesh_.reset();
  meshProblem_.clear();
  try {
    if (!path.isEmpty()) mesh_ = std::make_shared<const Mesh>(loadMesh(path.toStdString()));
  } catch (const InputError& e) {
    meshProblem_ = QString::fromUtf8(e.what());
  }
  if (mesh_) {
    const glm::vec3 size = meshBounds(mesh_->positions).size();
    meshInfo_->setText(tr("%1 triangles, %2 × %3 × %4 mm")
                           .arg(mesh_->triangles.size())
                           .arg(size.x, 0, 'f', 1)
                           .arg(size.y, 0, 'f', 1)
                           .arg(size.z, 0, 'f', 1));
  } else {
    meshInfo_->clear();
  }
  updatePart();
}

void PartExportDialog::setPath(const QString& path) {
  path_->setText(path);
}

QString PartExportDialog::path() const {
  return path_->text();
}

void PartExportDialog::setPlacement(const PartPlacement& p) {
  // The boxes are blocked so the part is placed once, at the end.
  for (int i = 0; i < 3; ++i) {
    const QSignalBlocker t(translation_[i]), r(rotation_[i]);
    translation_[i]->setValue(p.translationMm[i]);
    rotation_[i]->setValue(p.rotationDeg[i]);
  }
  const QSignalBlocker s(scale_), c(centre_);
  scale_->setValue(p.scale);
  centre_->setChecked(p.centreInBlock);
  updatePart();
}

PartPlacement PartExportDialog::placement() const {
  PartPlacement p;
  for (int i = 0; i < 3; ++i) {
    p.translationMm[i] = float(translation_[i]->value());
    p.rotationDeg[i] = float(rotation_[i]->value());
  }
  p.scale = float(scale_->value());
  p.centreInBlock = centre_->isChecked();
  return p;
}

void PartExportDialog::setTextureResolution(int texels) {
  resolution_->setValue(texels);
}

QString PartExportDialog::fitText() const {
  return fit_->text();
}

ExportRequest PartExportDialog::request() const {
  ExportRequest r;
  r.out = path_->text().toStdString();
  r.part.mesh = meshPath_->text().toStdString();
  r.part.placement = placement();
  r.part.textureResolution = resolution_->value();
  return r;
}

void PartExportDialog::accept() {
  try {
    if (!mesh_)
      throw InputError(meshProblem_.isEmpty() ? "choose a mesh (OBJ, STL or PLY)"
                                              : meshProblem_.toStdString());
    if (exportKindOf(request()) != ExportKind::Part)
      throw InputError("a part is written as " + extensionList(ExportKind::Part));
  } catch (const InputError& e) {
    problem_->setText(QString::fromUtf8(e.what()));
    problem_->show();
    return;
  }
  QDialog::accept();
}

void PartExportDialog::browseMesh() {
  const QString chosen = QFileDialog::getOpenFileName(this, tr("Part Mesh"), meshPath_->text(),
                                                      tr("Meshes (*.obj *.stl *.ply);;All files (*)"));
  if (!chosen.isEmpty()) setMeshPath(chosen);
}

void PartExportDialog::browseOut() {
  const QString chosen =
      QFileDialog::getSaveFileName(this, tr("Export Part"), path(), exportFormatFilters(ExportKind::Part));
  if (!chosen.isEmpty()) setPath(chosen);
}

void PartExportDialog::formatChanged() {
  const QFileInfo info(path());
  setPath(QDir(info.path()).filePath(info.completeBaseName() + format_->currentData().toString()));
}

void PartExportDialog::updatePart() {
  problem_->hide();
  if (!mesh_) {
    fits_ = false;
    fit_->setStyleSheet(meshProblem_.isEmpty() ? QString() : "color: #c0392b");
    fit_->setText(meshProblem_.isEmpty() ? tr("Choose a mesh to place in the block.") : meshProblem_);
    emit partChanged(nullptr);
    return;
  }
  auto placed = std::make_shared<const Mesh>(placeMesh(*mesh_, placement()));
  const PartFit fit = checkPartFit(block_, placed->positions);
  fits_ = fit.fits();
  QString text = QString::fromStdString(fit.describe());
  text[0] = text[0].toUpper();
  if (!fits_) text += tr(". It is exported anyway; beyond the block the wood is the model continued.");
  fit_->setStyleSheet(fits_ ? "color: #2e7d32" : "color: #c0392b");
  fit_->setText(text);
  emit partChanged(std::move(placed));
}

}  // namespace kerf
