#pragma once
// File ▸ Export: Face Image, Cut Image (the document's cut plane), Volume and Depth Stack open an
// ExportDialog (returned, non-modal); Part… a modeless PartExportDialog whose placed part shows in the 3D
// view while it is open. Each request runs as a background job (startExport, also for tests), ending in
// exportFinished or exportFailed (with a message box); several may run at once.
#include <vector>

#include "document_jobs.hpp"
#include "editor_controller.hpp"
#include "export_dialog.hpp"

namespace kerf {

class PartExportDialog;
class Viewport3D;

class ExportController : public EditorController {
  Q_OBJECT

 public:
  ExportController(const EditorContext& context, RenderSettings settings, Viewport3D* viewport);

  ExportDialog* showExportDialog(ExportDialog::Kind kind);
  PartExportDialog* showPartExportDialog();
  int startExport(ExportRequest request);  // the document's ring uncertainty filled in
  // All six model faces as PNG, into a folder the user chooses.
  void exportFaces();

 signals:
  // An export job wrote its file(s) (message: what was written), or failed / was cancelled.
  void exportFinished(const QString& path, const QString& message);
  void exportFailed(const QString& message);

 private:
  bool forget(int id);  // true if `id` was one of the exports

  RenderSettings settings_;
  Viewport3D* viewport_;
  std::vector<int> exportJobs_;
};

}  // namespace kerf
