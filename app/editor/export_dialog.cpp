#include "export_dialog.hpp"

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
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <algorithm>
#include <cmath>

#include "export_format_box.hpp"
#include "util/error.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

QString titleOf(ExportDialog::Kind kind) {
  switch (kind) {
    case ExportDialog::Kind::FaceImage:
      return QObject::tr("Export Face Image");
    case ExportDialog::Kind::CutImage:
      return QObject::tr("Export Cut Image");
    case ExportDialog::Kind::Volume:
      return QObject::tr("Export Volume");
    case ExportDialog::Kind::DepthStack:
      return QObject::tr("Export Depth Stack");
  }
  return {};
}

QString defaultName(ExportDialog::Kind kind) {
  switch (kind) {
    case ExportDialog::Kind::FaceImage:
      return "face_A.png";
    case ExportDialog::Kind::CutImage:
      return "cut.png";
    case ExportDialog::Kind::Volume:
      return "growth.nrrd";
    case ExportDialog::Kind::DepthStack:
      return "depth_stack";
  }
  return {};
}

}  // namespace

ExportDialog::ExportDialog(Kind kind, const Block& block, std::optional<CutPlane> cut, const QString& folder,
                           QWidget* parent)
    : QDialog(parent), kind_(kind), block_(block), cut_(cut) {
  setWindowTitle(titleOf(kind));
  auto* form = new QFormLayout;

  path_ = new QLineEdit(QDir(folder).filePath(defaultName(kind)));
  auto* browseButton = new QPushButton(tr("Browse…"));
  auto* pathRow = new QHBoxLayout;
  pathRow->addWidget(path_, 1);
  pathRow->addWidget(browseButton);
  form->addRow(kind == Kind::DepthStack ? tr("Folder:") : tr("File:"), pathRow);
  connect(browseButton, &QPushButton::clicked, this, &ExportDialog::browse);

  if (kind == Kind::Volume) {
    addVolumeRows(form);
  } else if (kind == Kind::DepthStack) {
    addDepthRows(form);
  } else {
    addImageRows(form);
  }
  sizeNote_ = new QLabel;
  sizeNote_->setWordWrap(true);  // a refusal is a sentence or two
  form->addRow(sizeNote_);
  problem_ = new QLabel;
  problem_->setStyleSheet("color: #c0392b");
  problem_->setWordWrap(true);
  problem_->hide();
  form->addRow(problem_);

  connect(path_, &QLineEdit::textChanged, this, &ExportDialog::pathChanged);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
  connect(buttons, &QDialogButtonBox::accepted, this, &ExportDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &ExportDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);
  if (format_) formatChanged();
  updateSizeNote();
}

void ExportDialog::addImageRows(QFormLayout* form) {
  format_ = new QComboBox;
  addExportFormats(format_, ExportKind::Image);
  format_->setToolTip(
      tr("PNG for CAM software and viewers; TIFF for 16-bit colour and a float growth page; "
         "OpenEXR for compositing and float data. Every file stores its scale (DPI)."));
  form->addRow(tr("Format:"), format_);
  connect(format_, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
  if (kind_ == Kind::FaceImage) {
    face_ = new QComboBox;
    for (FaceId face : kAllFaces) face_->addItem(QString(QChar(faceLetter(face))));
    face_->setToolTip(tr("The block face to render (A..F, Mokume's unfolding: docs/coordinates.md)"));
    form->addRow(tr("Face:"), face_);
    connect(face_, &QComboBox::currentIndexChanged, this, &ExportDialog::updateSizeNote);
  }
  pxPerMm_ = new QDoubleSpinBox;
  pxPerMm_->setRange(0.1, 400.0);
  pxPerMm_->setDecimals(2);
  pxPerMm_->setValue(10.0);
  pxPerMm_->setSuffix(tr(" px/mm"));
  pxPerMm_->setToolTip(
      tr("True scale: pixels per millimetre of wood. 10 px/mm = 254 DPI, stored in the file "
         "so CAM and layout software size the image correctly."));
  form->addRow(tr("Resolution:"), pxPerMm_);
  connect(pxPerMm_, &QDoubleSpinBox::valueChanged, this, &ExportDialog::updateSizeNote);
  samples_ = new QSpinBox;
  samples_->setRange(1, 8);
  samples_->setValue(2);
  samples_->setToolTip(
      tr("Supersamples per pixel side: 2 averages 2 x 2 points per pixel, as a camera does, "
         "so pores do not alias"));
  form->addRow(tr("Samples:"), samples_);
  pngLayer_ = new QComboBox;
  pngLayer_->addItem(tr("Colour"), "colour");
  pngLayer_->addItem(tr("Growth field (16-bit grey)"), "growth");
  pngLayer_->addItem(tr("Ring lines"), "rings");
  pngLayer_->setToolTip(
      tr("A PNG holds one layer: the wood's colour, the growth field (years since the pith, "
         "scaled to the image's range) or the ring lines"));
  form->addRow(tr("PNG layer:"), pngLayer_);
  extraLayers_ = new QCheckBox(tr("Growth field and ring lines as extra layers"));
  extraLayers_->setChecked(true);
  extraLayers_->setToolTip(
      tr("TIFF: two more pages (growth as 32-bit float years, rings as 16-bit grey). "
         "OpenEXR: channels \"growth\" and \"rings\""));
  form->addRow(QString(), extraLayers_);
  exrType_ = new QComboBox;
  exrType_->addItem(tr("Half float (16-bit)"), true);
  exrType_->addItem(tr("Float (32-bit)"), false);
  exrType_->setToolTip(
      tr("Precision of the OpenEXR colour and ring channels; the growth channel is always "
         "32-bit float"));
  form->addRow(tr("EXR type:"), exrType_);
}

void ExportDialog::addVolumeRows(QFormLayout* form) {
  format_ = new QComboBox;
  addExportFormats(format_, ExportKind::Volume);
  format_->setToolTip(
      tr("NRRD is written slice by slice with little memory; OpenVDB keeps the whole grid in "
         "memory until it is written (about 4 bytes per voxel for growth, 12 for colour)"));
  form->addRow(tr("Format:"), format_);
  connect(format_, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
  quantity_ = new QComboBox;
  quantity_->addItem(tr("Growth field (years since the pith)"), "growth");
  quantity_->addItem(tr("Colour (RGB)"), "color");
  quantity_->addItem(tr("How sure the rings are (mm, 1 sigma)"), "ring-uncertainty");
  quantity_->setToolTip(
      tr("Growth: float years, whose whole-year iso-surfaces are the rings. Colour: the wood "
         "as it would look on a cut at every voxel. How sure: float mm, how far a ring may lie from "
         "where the fit puts it (known after a fit)"));
  form->addRow(tr("Quantity:"), quantity_);
  resolution_ = new QSpinBox;
  resolution_->setRange(2, 2048);
  resolution_->setValue(256);
  resolution_->setToolTip(tr("Samples along the block's longest side; the other sides get the same spacing"));
  form->addRow(tr("Resolution:"), resolution_);
  connect(resolution_, &QSpinBox::valueChanged, this, &ExportDialog::updateSizeNote);
}

void ExportDialog::addDepthRows(QFormLayout* form) {
  face_ = new QComboBox;
  for (FaceId face : kAllFaces) face_->addItem(QString(QChar(faceLetter(face))));
  face_->setToolTip(tr("The face the router mills into"));
  form->addRow(tr("Face:"), face_);
  step_ = new QDoubleSpinBox;
  step_->setRange(0.01, 100.0);
  step_->setValue(1.0);
  step_->setSuffix(tr(" mm"));
  step_->setToolTip(tr("Depth removed between two images"));
  form->addRow(tr("Step:"), step_);
  depth_ = new QDoubleSpinBox;
  depth_->setRange(0.0, 1000.0);
  depth_->setValue(5.0);
  depth_->setSuffix(tr(" mm"));
  depth_->setToolTip(tr("The deepest surface; it must stay inside the block"));
  form->addRow(tr("Depth:"), depth_);
  pxPerMm_ = new QDoubleSpinBox;
  pxPerMm_->setRange(0.1, 400.0);
  pxPerMm_->setValue(10.0);
  pxPerMm_->setSuffix(tr(" px/mm"));
  pxPerMm_->setToolTip(tr("True scale of every image; stored in each PNG as DPI"));
  form->addRow(tr("Resolution:"), pxPerMm_);
  samples_ = new QSpinBox;
  samples_->setRange(1, 8);
  samples_->setValue(2);
  samples_->setToolTip(tr("Supersamples per pixel side"));
  form->addRow(tr("Samples:"), samples_);
  for (auto* box : {step_, depth_, pxPerMm_})
    connect(box, &QDoubleSpinBox::valueChanged, this, &ExportDialog::updateSizeNote);
  connect(face_, &QComboBox::currentIndexChanged, this, &ExportDialog::updateSizeNote);
}

void ExportDialog::setPath(const QString& path) {
  path_->setText(path);
}

QString ExportDialog::path() const {
  return path_->text();
}

void ExportDialog::setPxPerMm(double pxPerMm) {
  if (pxPerMm_) pxPerMm_->setValue(pxPerMm);
}

ExportRequest ExportDialog::request() const {
  ExportRequest r;
  r.out = path_->text().toStdString();
  if (pxPerMm_) r.pxPerMm = static_cast<float>(pxPerMm_->value());
  if (samples_) r.samples = samples_->value();
  if (pngLayer_) r.image.pngLayer = imageLayerFromName(pngLayer_->currentData().toString().toStdString());
  if (extraLayers_) r.image.extraLayers = extraLayers_->isChecked();
  if (exrType_) r.image.exrHalf = exrType_->currentData().toBool();
  if (quantity_) r.quantity = volumeQuantityFromName(quantity_->currentData().toString().toStdString());
  if (resolution_) r.resolution = resolution_->value();
  const FaceId face = face_ ? kAllFaces[face_->currentIndex()] : FaceId::A;
  if (kind_ == Kind::FaceImage) r.face = face;
  if (kind_ == Kind::CutImage) r.plane = cut_;
  if (kind_ == Kind::DepthStack) {
    DepthStackOptions stack;
    stack.face = face;
    stack.stepMm = static_cast<float>(step_->value());
    stack.depthMm = static_cast<float>(depth_->value());
    r.depthStack = stack;
  }
  return r;
}

void ExportDialog::accept() {
  try {
    const ExportRequest r = request();
    const ExportKind kind = exportKindOf(r);
    const bool expected = kind_ == Kind::Volume       ? kind == ExportKind::Volume
                          : kind_ == Kind::DepthStack ? kind == ExportKind::DepthStack
                                                      : kind == ExportKind::Image;
    if (!expected) throw InputError("the file name's extension does not match the chosen format");
    if (kind_ == Kind::CutImage && !(cut_ && cut_->boundsInBlock(block_)))
      throw InputError("the cut plane does not pass through the block");
  } catch (const InputError& e) {
    problem_->setText(QString::fromUtf8(e.what()));
    problem_->show();
    return;
  }
  QDialog::accept();
}

void ExportDialog::browse() {
  QString chosen;
  if (kind_ == Kind::DepthStack) {
    chosen = QFileDialog::getExistingDirectory(this, titleOf(kind_), QFileInfo(path()).absolutePath());
  } else {
    chosen = QFileDialog::getSaveFileName(this, titleOf(kind_), path(), selectedFormatFilter(format_));
  }
  if (!chosen.isEmpty()) setPath(chosen);
}

void ExportDialog::formatChanged() {
  const QString extension = format_->currentData().toString();
  const QFileInfo info(path());
  setPath(QDir(info.path()).filePath(info.completeBaseName() + extension));
  updateLayerControls();
}

void ExportDialog::pathChanged() {
  if (!format_) return;
  // A typed (or set) extension picks the format, so the two never disagree.
  selectExportFormatOf(format_, path());
  updateLayerControls();
}

void ExportDialog::updateLayerControls() {
  const QString extension = format_ ? format_->currentData().toString() : QString();
  if (pngLayer_) pngLayer_->setEnabled(extension == ".png");
  if (extraLayers_) extraLayers_->setEnabled(extension != ".png");
  if (exrType_) exrType_->setEnabled(extension == ".exr");
  updateSizeNote();
}

QString ExportDialog::sizeNote() const {
  return sizeNote_ ? sizeNote_->text() : QString();
}

void ExportDialog::updateSizeNote() {
  if (!sizeNote_) return;
  if (kind_ == Kind::Volume) {
    const glm::vec3 size = block_.size();
    const float longest = std::max({size.x, size.y, size.z});
    const int n = resolution_->value();
    glm::ivec3 count;
    for (int a = 0; a < 3; ++a) count[a] = std::max(1, static_cast<int>(std::lround(n * size[a] / longest)));
    const double voxels = double(count.x) * count.y * count.z;
    const double bytes = voxels * (quantity_->currentData().toString() == "color" ? 3 : 4);
    sizeNote_->setText(tr("%1 × %2 × %3 voxels, about %4 MiB uncompressed")
                           .arg(count.x)
                           .arg(count.y)
                           .arg(count.z)
                           .arg(bytes / 1048576.0, 0, 'f', 1));
    return;
  }
  const double pxPerMm = pxPerMm_->value();
  if (kind_ == Kind::CutImage) {
    sizeNote_->setText(
        tr("%1 DPI; the image covers the cut's extent in the block").arg(pxPerMm * 25.4, 0, 'f', 1));
    return;
  }
  const glm::ivec2 px = block_.faceImageSize(kAllFaces[face_->currentIndex()], static_cast<float>(pxPerMm));
  QString note = tr("%1 × %2 px, %3 DPI").arg(px.x).arg(px.y).arg(pxPerMm * 25.4, 0, 'f', 1);
  if (kind_ == Kind::DepthStack)
    note += tr(", %1 images").arg(static_cast<int>(std::floor(depth_->value() / step_->value() + 1e-4)) + 1);
  try {  // say at once what the export would refuse (util/size_limits.hpp)
    checkImageSize(px, "the image", static_cast<float>(pxPerMm));
  } catch (const InputError& e) {
    QString why = QString::fromUtf8(e.what());
    why[0] = why[0].toUpper();
    note = QStringLiteral("<span style='color:#e05050'>%1.</span>").arg(why.toHtmlEscaped());
  }
  sizeNote_->setText(note);
  if (layout()) {  // grow to show a wrapped refusal whole; never shrink under the user's hands
    layout()->activate();
    if (heightForWidth(width()) > height()) resize(width(), heightForWidth(width()));
  }
}

}  // namespace kerf
