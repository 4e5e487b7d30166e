// MainWindow: the actions of the work: the Rings and Texture menus, File ▸ Export and the log entries of the
// File menu, each wired to its controller.
#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>

#include "annotation_layer.hpp"
#include "appearance_controller.hpp"
#include "faces_view.hpp"
#include "main_window.hpp"

namespace kerf {

void MainWindow::createRingsMenu() {
  QMenu* rings = menuBar()->addMenu(tr("&Rings"));
  rings->setObjectName("ringsMenu");
  rings->setToolTipsVisible(true);
  detectRingsAction_ = rings->addAction(tr("&Detect Rings"), rings_, &RingsController::detectRings);
  detectRingsAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
  detectRingsAction_->setToolTip(tr(
      "Find the annual rings on every face photo and add them as ring traces you can correct (they "
      "replace the previously detected ones; your own traces stay); runs in the background (Esc cancels)"));
  learnedDetectorAction_ = rings->addAction(tr("&Learned Ring Detector"));
  learnedDetectorAction_->setObjectName("learnedDetectorAction");
  learnedDetectorAction_->setCheckable(true);
  learnedDetectorAction_->setToolTip(tr(
      "Detect Rings and Reconstruct use Kerf's network, trained on wood Kerf rendered itself: it tells the "
      "ring boundary (latewood meeting next year's earlywood) from the other, softer edge of the latewood "
      "band. Off: the classical filter detector. Remembered between sessions"));
  const bool learned =
      QSettings().value("rings/detector", QString(kDefaultEditorRingDetector)).toString() == "learned";
  learnedDetectorAction_->setChecked(learned);
  rings_->setDetector(learned ? "learned" : "classical");
  connect(learnedDetectorAction_, &QAction::toggled, this, [this](bool on) {
    rings_->setDetector(on ? "learned" : "classical");
    QSettings().setValue("rings/detector", on ? "learned" : "classical");
  });
  fitGrowthAction_ = rings->addAction(tr("&Fit Growth Field"), rings_, &RingsController::fitGrowthField);
  fitGrowthAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
  fitGrowthAction_->setToolTip(
      tr("Fit the pith axis, ring width, growth rates and wood colours to your ring traces (detected and "
         "corrected, numbered ones keep their years) and the ring images, as kerf-cli fit does; the faces "
         "and the 3D view follow the fit live; one undo step"));
  otherPithAction_ = rings->addAction(tr("Use &Other Pith Candidate"));  // RingsController::setActions
  otherPithAction_->setEnabled(false);
  otherPithAction_->setToolTip(
      tr("When the rings on the faces are nearly parallel, the pith could lie on either side of the block "
         "(Mokume B.1): switch to the field fitted around the other side (one undo step; again to switch "
         "back)"));
  showResidualsAction_ = rings->addAction(tr("Show Fit &Residuals"));
  showResidualsAction_->setCheckable(true);
  showResidualsAction_->setChecked(true);
  showResidualsAction_->setEnabled(false);
  showResidualsAction_->setToolTip(
      tr("Colour every fitted ring line by how well the fitted rings follow it: green within 3 % of a ring "
         "width, yellow about 10 %, red 20 % or more (a wrong or broken trace)"));
  connect(showResidualsAction_, &QAction::toggled, facesView_, &FacesView::setOverlayVisible);
  rings->addSeparator();
  rings->addAction(showContoursAction_);
  exportAnnotationsAction_ =
      rings->addAction(tr("Export &Mokume Annotations…"));  // RingsController::setActions
  exportAnnotationsAction_->setToolTip(
      tr("Write the numbered ring traces (X_ann.png: pixel = year) and knot marks (X_knot.png) in the Mokume "
         "sample format, at the size of the face photos"));
  exportAnnotationsAction_->setEnabled(false);
  QMenu* tracing = rings->addMenu(tr("&Tracing Tools"));  // the faces view's tool bar, with their keys
  tracing->setToolTipsVisible(true);
  tracing->addActions(annotationLayer_->toolActions());
  tracing->addSeparator();
  tracing->addActions(annotationLayer_->editActions());
  rings_->setActions({showContoursAction_, showResidualsAction_, otherPithAction_, exportAnnotationsAction_});
}

void MainWindow::createTextureMenu() {
  QMenu* texture = menuBar()->addMenu(tr("&Texture"));
  texture->setToolTipsVisible(true);
  inferTextureAction_ =
      texture->addAction(tr("&Infer Texture from Photos"), texture_, &TextureController::inferTexture);
  inferTextureAction_->setToolTip(tr(
      "Find the pores, rays and fibres (sizes, spacing, darkness) and the wood colours that make the faces "
      "look like the photos, each face compared with its own photo (end grain and side grain differ); fit "
      "the growth field first. Runs in the background (Esc cancels), the faces follow live; one undo step"));
  texture->addSeparator();
  texture->addAction(appearance_->photoTrueAction());
}

void MainWindow::createExportActions(QMenu* exportMenu) {
  const struct {
    ExportDialog::Kind kind;
    QString text, tip;
  } entries[] = {
      {ExportDialog::Kind::FaceImage, tr("&Face Image…"),
       tr("A face at true scale as PNG, 16-bit TIFF or OpenEXR, with the growth field and ring lines as "
          "layers")},
      {ExportDialog::Kind::CutImage, tr("&Cut Image…"),
       tr("The surface of the current cut plane at true scale, with the growth field and ring lines as "
          "layers")},
      {ExportDialog::Kind::Volume, tr("&Volume…"),
       tr("The growth field or the colour through the whole block, as NRRD or OpenVDB")},
      {ExportDialog::Kind::DepthStack, tr("&Depth Stack…"),
       tr("A face after milling away 0 .. D mm in steps, as numbered PNGs with an index of depths")},
  };
  for (const auto& entry : entries) {
    QAction* action = exportMenu->addAction(entry.text, exports_,
                                            [this, kind = entry.kind] { exports_->showExportDialog(kind); });
    action->setToolTip(entry.tip);
    action->setStatusTip(entry.tip);
    exportActions_[static_cast<int>(entry.kind)] = action;
  }
  QAction* part = exportMenu->addAction(tr("&Part…"), exports_, [this] { exports_->showPartExportDialog(); });
  part->setStatusTip(
      tr("A mesh (OBJ, STL, PLY) placed in the block, baked with its wood as OBJ+MTL+PNG or "
         "glTF; shown in the 3D view while you place it"));
  exportMenu->addSeparator();
  exportMenu->addAction(tr("All Model Faces as PNG…"), exports_, &ExportController::exportFaces);
}

void MainWindow::createLogActions(QMenu* file) {
  QAction* open = file->addAction(tr("Open &Log…"), logBoard_, &LogBoardController::chooseLog);
  open->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
  open->setToolTip(
      tr("Open a tree log (a Kerf .kerflog file, or a Gran_1 folder of CT data) and cut a "
         "board from it"));
  file->addAction(tr("New &Random Log…"), logBoard_, &LogBoardController::chooseRandomLog);
  saveLogAction_ = file->addAction(tr("Save Log &As…"));  // LogBoardController::setActions
  saveLogAction_->setEnabled(false);
  closeLogAction_ = file->addAction(tr("Close Lo&g"));
  closeLogAction_->setToolTip(tr("Back to the block's own wood model (undoable)"));
  closeLogAction_->setEnabled(false);
}

}  // namespace kerf
