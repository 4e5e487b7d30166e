#pragma once
// File > Export dialogs: a face image, a cut image, a volume or a depth stack, with the format, resolution
// and layer choices of `kerf-cli export` (core/export/export_job.hpp). The dialog only describes the export
// (request()); MainWindow runs it as a background job. Tests fill setPath() and accept() it.
#include <QDialog>
#include <optional>

#include "export/export_job.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace kerf {

class ExportDialog : public QDialog {
  Q_OBJECT

 public:
  enum class Kind { FaceImage, CutImage, Volume, DepthStack };

  // `cut` is the document's cut plane (CutImage); `folder` where the path starts.
  ExportDialog(Kind kind, const Block& block, std::optional<CutPlane> cut, const QString& folder,
               QWidget* parent = nullptr);

  Kind kind() const { return kind_; }
  void setPath(const QString& path);
  QString path() const;
  // The line under the settings: the image or volume size, or why it cannot be made.
  QString sizeNote() const;
  void setPxPerMm(double pxPerMm);
  // The export as chosen; valid once accept() has let the dialog close.
  ExportRequest request() const;

  void accept() override;  // checks the request (exportKindOf); shows the problem in the dialog instead

 private:
  void addImageRows(QFormLayout* form);
  void addVolumeRows(QFormLayout* form);
  void addDepthRows(QFormLayout* form);
  void browse();
  void formatChanged();  // the format's extension replaces the path's
  void pathChanged();    // the path's extension picks the format
  void updateLayerControls();
  void updateSizeNote();

  Kind kind_;
  Block block_;
  std::optional<CutPlane> cut_;
  QLineEdit* path_ = nullptr;
  QComboBox* format_ = nullptr;
  QComboBox* face_ = nullptr;
  QDoubleSpinBox* pxPerMm_ = nullptr;
  QSpinBox* samples_ = nullptr;
  QComboBox* pngLayer_ = nullptr;
  QCheckBox* extraLayers_ = nullptr;
  QComboBox* exrType_ = nullptr;
  QComboBox* quantity_ = nullptr;
  QSpinBox* resolution_ = nullptr;
  QDoubleSpinBox* step_ = nullptr;
  QDoubleSpinBox* depth_ = nullptr;
  QLabel* sizeNote_ = nullptr;
  QLabel* problem_ = nullptr;
};

}  // namespace kerf
