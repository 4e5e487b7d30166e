// MainWindow: its controllers made on its views, their voices (log, message boxes, status bar) routed to
// the window, and their news forwarded as the window's signals.
#include <QActionGroup>
#include <QDockWidget>
#include <QStatusBar>
#include <QToolBar>

#include "appearance_controller.hpp"
#include "cut_photo_controller.hpp"
#include "faces_view.hpp"
#include "main_window.hpp"
#include "parameter_panel.hpp"

namespace kerf {

void MainWindow::createControllers(RenderSettings settings) {
  const EditorContext context{this, document_, jobs_};
  faces_ = new FacesController(context, settings, facesView_, viewport_, cutView_);
  rings_ = new RingsController(context, faces_, facesView_, annotationLayer_);
  texture_ = new TextureController(context, faces_, rings_);
  appearance_ = new AppearanceController(context, settings, faces_, cutView_, viewport_);
  logBoard_ = new LogBoardController(
      context, faces_,
      {logView_, boardControls_, knotTable_, panelControls_, panelPane_, viewport_, cutView_});
  blockKnots_ = new BlockKnotsController(context, blockKnotTable_, findChild<QDockWidget*>("blockKnotsDock"),
                                         annotationLayer_);
  exports_ = new ExportController(context, settings, viewport_);
  files_ = new FilesController(context, faces_);
  cutPhoto_ = new CutPhotoController(context, cutView_);
  cutBar_->addAction(cutPhoto_->loadAction());
  cutBar_->addAction(cutPhoto_->alignAction());
  cutBar_->addAction(cutPhoto_->removeAction());
  cutDisplayBar_->addActions(cutPhoto_->displayGroup()->actions());
  connect(appearance_, &AppearanceController::cutMade, cutPhoto_, &CutPhotoController::modelSideChanged);
  for (EditorController* controller : std::initializer_list<EditorController*>{
           faces_, rings_, texture_, appearance_, logBoard_, blockKnots_, exports_, files_, cutPhoto_})
    connectController(controller);
  connect(facesView_, &FacesView::photoDropped, files_, &FilesController::dropPhoto);
  connect(facesView_, &FacesView::documentDropped, files_, &FilesController::openInstead);
  connect(files_, &FilesController::speciesOpened, parameterPanel_, &ParameterPanel::setCurrentPreset);
  forwardSignals();
}

void MainWindow::connectController(EditorController* controller) {
  connect(controller, &EditorController::logged, this, &MainWindow::logMessage);
  connect(controller, &EditorController::alerted, this, &MainWindow::showAlert);
  connect(controller, &EditorController::statusShown, statusBar(), &QStatusBar::showMessage);
}

void MainWindow::forwardSignals() {
  connect(faces_, &FacesController::facesRendered, this, &MainWindow::facesRendered);
  connect(faces_, &FacesController::facesPreviewed, this, &MainWindow::facesPreviewed);
  connect(faces_, &FacesController::documentReady, this, &MainWindow::documentReady);
  connect(rings_, &RingsController::ringsDetected, this, &MainWindow::ringsDetected);
  connect(rings_, &RingsController::growthFieldFitted, this, &MainWindow::growthFieldFitted);
  connect(rings_, &RingsController::fitPreviewed, this, &MainWindow::fitPreviewed);
  connect(rings_, &RingsController::ringJobFailed, this, &MainWindow::ringJobFailed);
  connect(texture_, &TextureController::textureInferred, this, &MainWindow::textureInferred);
  connect(texture_, &TextureController::texturePreviewed, this, &MainWindow::texturePreviewed);
  connect(texture_, &TextureController::textureJobFailed, this, &MainWindow::textureJobFailed);
  connect(logBoard_, &LogBoardController::logOpened, this, &MainWindow::logOpened);
  connect(logBoard_, &LogBoardController::panelRendered, this, &MainWindow::panelRendered);
  connect(exports_, &ExportController::exportFinished, this, &MainWindow::exportFinished);
  connect(exports_, &ExportController::exportFailed, this, &MainWindow::exportFailed);
  connect(files_, &FilesController::documentOpened, this, &MainWindow::documentOpened);
  connect(files_, &FilesController::documentFailed, this, &MainWindow::documentFailed);
  connect(files_, &FilesController::photosImported, this, &MainWindow::photosImported);
}

}  // namespace kerf
