#pragma once
// File > Export > Part…: a mesh placed in the block and baked with its wood (issue 7; core/export/
// part_export.hpp), the editor's side of `kerf-cli export --mesh`. The dialog loads the mesh, takes the
// placement (position, rotation about x then y then z, scale, or centred in the block) and the texture
// resolution, and says live whether the part fits in the block. While it is open the placed part is
// shown in the 3D view (partChanged). It is modeless, so the 3D view can be orbited meanwhile; accept()
// checks the request, and MainWindow runs it as a background job. A part that sticks out is exported
// with a warning, as on the command line.
#include <QDialog>
#include <memory>

#include "export/export_job.hpp"
#include "mesh/mesh.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace kerf {

class PartExportDialog : public QDialog {
  Q_OBJECT

 public:
  PartExportDialog(const Block& block, const QString& folder, QWidget* parent = nullptr);

  void setMeshPath(const QString& path);  // loads it (a failure shows in the fit line)
  void setPath(const QString& path);
  QString path() const;
  void setPlacement(const PartPlacement& placement);
  PartPlacement placement() const;
  void setTextureResolution(int texels);
  bool meshLoaded() const { return mesh_ != nullptr; }
  QString fitText() const;  // the fit line as shown
  bool fits() const { return fits_; }
  // The export as chosen; valid once accept() has let the dialog close.
  ExportRequest request() const;

  void accept() override;

 signals:
  // The placed part to show in the 3D view (null: none, e.g. no mesh or the dialog closed).
  void partChanged(std::shared_ptr<const kerf::Mesh> placedMesh);

 private:
  void browseMesh();
  void browseOut();
  void formatChanged();
  void updatePart();  // placement or mesh changed: fit line and preview

  Block block_;
  std::shared_ptr<const Mesh> mesh_;
  QString meshProblem_;
  bool fits_ = false;
  QLineEdit* meshPath_ = nullptr;
  QLineEdit* path_ = nullptr;
  QComboBox* format_ = nullptr;
  QDoubleSpinBox* translation_[3] = {};
  QDoubleSpinBox* rotation_[3] = {};
  QDoubleSpinBox* scale_ = nullptr;
  QCheckBox* centre_ = nullptr;
  QSpinBox* resolution_ = nullptr;
  QLabel* meshInfo_ = nullptr;
  QLabel* fit_ = nullptr;
  QLabel* problem_ = nullptr;
};

}  // namespace kerf
