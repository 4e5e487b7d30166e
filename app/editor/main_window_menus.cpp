// MainWindow: the File, Edit, View and Help menus; each action wired to the controller that does its work.
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QMenuBar>
#include <QMessageBox>

#include "cut_photo_controller.hpp"
#include "cut_view.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "main_window.hpp"
#include "viewport3d.hpp"
#include "window_layout.hpp"

namespace kerf {

void MainWindow::createMenus() {
  createFileMenu();

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  undoAction_ = document_->undoStack()->createUndoAction(this, tr("&Undo"));
  undoAction_->setShortcut(QKeySequence::Undo);
  redoAction_ = document_->undoStack()->createRedoAction(this, tr("&Redo"));
  redoAction_->setShortcuts({QKeySequence::Redo, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)});
  edit->addAction(undoAction_);
  edit->addAction(redoAction_);

  createViewMenu();
  createRingsMenu();  // main_window_work_menus.cpp
  createTextureMenu();

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About Kerf"), this, [this] {
    QMessageBox::about(this, tr("About Kerf"),
                       tr("<b>Kerf</b> %1<br>An editor for solid wood: the annual rings and texture inside a "
                          "block, from photos of its faces or from scratch.")
                           .arg(QApplication::applicationVersion()));
  });

  faces_->setDisplayControls(displayGroup_, toggleViewAction_, blendSlider_);
  logBoard_->setActions({saveLogAction_, closeLogAction_, showPhotosOn3dAction_});
}

void MainWindow::createFileMenu() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->setObjectName("fileMenu");
  file->addAction(tr("Open &Demo Block"), files_, [this] {
    if (files_->maybeSave()) files_->openDemo(defaultDemoFolder());
  });
  QAction* open =
      file->addAction(tr("&Open Project or Sample Folder…"), files_, &FilesController::chooseDocument);
  open->setShortcut(QKeySequence::Open);
  files_->setRecentMenu(file->addMenu(tr("Open &Recent")));
  importPhotosAction_ = file->addAction(tr("&Import Photos…"), files_, [this] { files_->importPhotos(); });
  importPhotosAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
  importPhotosAction_->setToolTip(
      tr("Make the face images from your own photos of the block: mark each face's corners, turn it, "
         "white-balance it, and set the block's size"));
  importPhotosAction_->setStatusTip(importPhotosAction_->toolTip());
  file->addAction(cutPhoto_->loadAction());
  createLogActions(file);  // main_window_work_menus.cpp
  file->addSeparator();
  QAction* saveAction = file->addAction(tr("&Save"), files_, [this] { files_->save(); });
  saveAction->setShortcut(QKeySequence::Save);
  QAction* saveAsAction = file->addAction(tr("Save &As…"), files_, [this] { files_->saveAs(); });
  saveAsAction->setShortcut(QKeySequence::SaveAs);
  file->addSeparator();
  createExportActions(file->addMenu(tr("&Export")));  // main_window_work_menus.cpp
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));
}

void MainWindow::createViewMenu() {
  QMenu* view = menuBar()->addMenu(tr("&View"));
  toggleViewAction_ = view->addAction(tr("Show &Model Rendering"));  // FacesController::toggleView
  toggleViewAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
  toggleViewAction_->setEnabled(false);
  QMenu* faces = view->addMenu(tr("&Faces Show"));
  faces->addActions(displayGroup_->actions());
  showPhotosOn3dAction_ = view->addAction(tr("Photos on the 3D &Block"));
  showPhotosOn3dAction_->setCheckable(true);
  showPhotosOn3dAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
  showPhotosOn3dAction_->setToolTip(
      tr("Project the face photos onto the 3D block to compare them with the model"));
  connect(showPhotosOn3dAction_, &QAction::toggled, viewport_, &Viewport3D::setShowPhotos);
  view->addAction(tr("Reset 3D &Camera"), viewport_, &Viewport3D::resetCamera)->setShortcut(Qt::Key_Home);
  showContoursAction_ = view->addAction(tr("Show Ring &Traces"));
  showContoursAction_->setCheckable(true);
  showContoursAction_->setChecked(true);
  showContoursAction_->setEnabled(false);
  showContoursAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
  showContoursAction_->setToolTip(
      tr("Draw the ring traces (detected and your own) and knot marks over the faces"));
  connect(showContoursAction_, &QAction::toggled, facesView_, &FacesView::setOverlayVisible);
  view->addAction(cutView_->showRingUncertaintyAction());
  QMenu* cut = view->addMenu(tr("C&ut Shows"));
  cut->addActions(cutPhoto_->displayGroup()->actions());
  cut->addSeparator();
  cut->addAction(cutPhoto_->alignAction());
  cut->addAction(cutPhoto_->removeAction());
  view->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());
  view->addAction(layout_->resetAction());
}

}  // namespace kerf
