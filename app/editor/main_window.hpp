#pragma once
// The editor's main window: the six faces unfolded next to the live 3D block, the parameter panel, the
// cut plane (3D gizmo, numeric controls and a true-scale cut panel), the log and the undo history.
// Every edit goes through the Document (undoable); every long task through the JobRunner (progress,
// cancel, never on the GUI thread). The window holds the layout, the docks, the menus and their wiring;
// the work is done by its controllers, each owning its jobs and state: FacesController (the rendered
// faces and what they show), RingsController (detection, fit, traces), TextureController,
// LogBoardController (logs, boards, panels), BlockKnotsController (the block's knot table), ExportController
// and FilesController (open, save, recent, recovery, import), and WorkPath (the start page and Reconstruct).
#include <QMainWindow>
#include <array>

#include "appearance_controller.hpp"
#include "block_knots_controller.hpp"
#include "export_controller.hpp"
#include "faces_controller.hpp"
#include "files_controller.hpp"
#include "log_board_controller.hpp"
#include "rings_controller.hpp"
#include "texture_controller.hpp"

class QAction;
class QActionGroup;
class QMenu;
class QLabel;
class QSlider;
class QSplitter;
class QStackedWidget;
class QTabWidget;
class QToolBar;
class QUndoView;

namespace kerf {

class AnnotationLayer;
class BlockKnotTable;
class BoardControls;
class CutPlaneControls;
class CutPhotoController;
class CutView;
class Document;
class FacesView;
class ImagePane;
class JobRunner;
class KnotTable;
class LogPanel;
class LogView;
class PanelControls;
class ParameterPanel;
class Viewport3D;
class WindowLayout;
class WorkPath;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(RenderSettings settings = {}, QWidget* parent = nullptr);
  ~MainWindow() override;

  // The controllers (see above).
  FacesController* faces() const { return faces_; }
  RingsController* rings() const { return rings_; }
  TextureController* texture() const { return texture_; }
  AppearanceController* appearance() const { return appearance_; }
  LogBoardController* logBoard() const { return logBoard_; }
  BlockKnotsController* blockKnots() const { return blockKnots_; }
  ExportController* exports() const { return exports_; }
  FilesController* files() const { return files_; }
  CutPhotoController* cutPhoto() const { return cutPhoto_; }
  // The start page, Open Photos, Reconstruct and the fit's quality in the status bar (work_path.hpp).
  WorkPath* workPath() const { return workPath_; }

  // The document's files, as main() and the tests open them (FilesController).
  void openDocument(const QString& path) { files_->openDocument(path); }
  void openDemo(const QString& folder, const DemoOptions& options = demoOptions()) {
    files_->openDemo(folder, options);
  }
  static DemoOptions demoOptions() { return FilesController::demoOptions(); }
  bool save() { return files_->save(); }
  bool saveAs(QString path = {}) { return files_->saveAs(std::move(path)); }
  void offerRecovery() { files_->offerRecovery(); }
  void recover(const QString& autosaveFile) { files_->recover(autosaveFile); }
  void setAskBeforeDiscarding(bool ask) { files_->setAskBeforeDiscarding(ask); }
  Autosave* autosave() const { return files_->autosave(); }

  bool isBusy() const;
  bool hasDocument() const { return faces_->hasDocument(); }
  bool showingPhotos() const { return faces_->showingPhotos(); }
  QString documentName() const;
  QString lastError() const { return lastError_; }
  // The window's voice: a line in the log; an error in the log and a (non-blocking) message box.
  void logMessage(const QString& level, const QString& text);
  void showError(const QString& message);

  Document* document() const { return document_; }
  JobRunner* jobs() const { return jobs_; }
  FacesView* facesView() const { return facesView_; }
  Viewport3D* viewport() const { return viewport_; }
  CutView* cutView() const { return cutView_; }
  ParameterPanel* parameterPanel() const { return parameterPanel_; }
  CutPlaneControls* cutControls() const { return cutControls_; }
  LogPanel* log() const { return log_; }
  WindowLayout* windowLayout() const { return layout_; }
  AnnotationLayer* annotationLayer() const { return annotationLayer_; }
  LogView* logView() const { return logView_; }
  BoardControls* boardControls() const { return boardControls_; }
  KnotTable* knotTable() const { return knotTable_; }
  BlockKnotTable* blockKnotTable() const { return blockKnotTable_; }  // the block's knots ("Knots" dock)
  PanelControls* panelControls() const { return panelControls_; }
  ImagePane* panelPane() const { return panelPane_; }

  // Photos, Model, Blend, Split, Difference (FaceDisplay order; Ctrl+1 .. Ctrl+5), and the slider of Blend
  // (opacity) and Split (where the line lies).
  QList<QAction*> faceDisplayActions() const;
  QSlider* faceSlider() const { return blendSlider_; }
  QAction* toggleViewAction() const { return toggleViewAction_; }
  QAction* undoAction() const { return undoAction_; }
  QAction* redoAction() const { return redoAction_; }
  QAction* showPhotosOn3dAction() const { return showPhotosOn3dAction_; }
  QAction* importPhotosAction() const { return importPhotosAction_; }
  QAction* detectRingsAction() const { return detectRingsAction_; }
  QAction* fitGrowthAction() const { return fitGrowthAction_; }
  QAction* otherPithAction() const { return otherPithAction_; }
  QAction* showResidualsAction() const { return showResidualsAction_; }
  QAction* showContoursAction() const { return showContoursAction_; }
  QAction* exportAnnotationsAction() const { return exportAnnotationsAction_; }
  QAction* inferTextureAction() const { return inferTextureAction_; }
  QAction* exportAction(ExportDialog::Kind kind) const { return exportActions_[static_cast<int>(kind)]; }

 signals:
  // The controllers' news, in one place for the window's observers (WorkPath, main(), the tests).
  void exportFinished(const QString& path, const QString& message);
  void exportFailed(const QString& message);
  void logOpened();
  void panelRendered();
  void documentOpened(const QString& path);
  void documentReady();  // loaded, and its faces rendered at full resolution
  void documentFailed(const QString& message);
  void facesRendered();
  void facesPreviewed();
  void ringsDetected();
  void growthFieldFitted();
  void fitPreviewed();
  void ringJobFailed(const QString& message);
  void photosImported();
  void textureInferred();
  void texturePreviewed();
  void textureJobFailed(const QString& message);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void createViews();
  QToolBar* createAnnotationBar(QWidget* parent);
  void createDocks();
  void createLogDocks();                        // main_window_docks.cpp
  void createPanelDock(QTabWidget* boardTabs);  // main_window_docks.cpp
  void createBlockKnotsDock();                  // main_window_docks.cpp
  void createControllers(RenderSettings settings);
  void connectController(EditorController* controller);
  void forwardSignals();
  void createMenus();  // main_window_menus.cpp
  void createFileMenu();
  void createViewMenu();
  void createRingsMenu();  // main_window_work_menus.cpp
  void createTextureMenu();
  void createExportActions(QMenu* exportMenu);
  void createLogActions(QMenu* file);
  void connectDocument();

  void applyPreset(const QString& presetId);
  void showAlert(const QString& text, const QString& error);
  void updateTitle();

  Document* document_ = nullptr;
  JobRunner* jobs_ = nullptr;
  QString lastError_;

  FacesController* faces_ = nullptr;
  RingsController* rings_ = nullptr;
  TextureController* texture_ = nullptr;
  AppearanceController* appearance_ = nullptr;
  LogBoardController* logBoard_ = nullptr;
  BlockKnotsController* blockKnots_ = nullptr;
  ExportController* exports_ = nullptr;
  FilesController* files_ = nullptr;
  CutPhotoController* cutPhoto_ = nullptr;
  QToolBar* cutBar_ = nullptr;         // the cut photo's commands
  QToolBar* cutDisplayBar_ = nullptr;  // what the cut shows
  WorkPath* workPath_ = nullptr;

  WindowLayout* layout_ = nullptr;
  QStackedWidget* facesStack_ = nullptr;  // the start page, then the faces
  QSplitter* centralSplitter_ = nullptr;  // the faces | 3D block
  FacesView* facesView_ = nullptr;
  AnnotationLayer* annotationLayer_ = nullptr;
  Viewport3D* viewport_ = nullptr;
  CutView* cutView_ = nullptr;
  ParameterPanel* parameterPanel_ = nullptr;
  CutPlaneControls* cutControls_ = nullptr;
  LogPanel* log_ = nullptr;
  QUndoView* history_ = nullptr;
  LogView* logView_ = nullptr;
  BoardControls* boardControls_ = nullptr;
  KnotTable* knotTable_ = nullptr;
  BlockKnotTable* blockKnotTable_ = nullptr;
  PanelControls* panelControls_ = nullptr;
  ImagePane* panelPane_ = nullptr;
  QSlider* blendSlider_ = nullptr;
  QLabel* cursorLabel_ = nullptr;
  QLabel* documentLabel_ = nullptr;

  QActionGroup* displayGroup_ = nullptr;
  QAction* toggleViewAction_ = nullptr;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* showPhotosOn3dAction_ = nullptr;
  QAction* importPhotosAction_ = nullptr;
  QAction* detectRingsAction_ = nullptr;
  QAction* learnedDetectorAction_ = nullptr;  // Rings ▸ Learned Ring Detector (checked: the network)
  QAction* fitGrowthAction_ = nullptr;
  QAction* otherPithAction_ = nullptr;
  QAction* showResidualsAction_ = nullptr;
  QAction* showContoursAction_ = nullptr;
  QAction* exportAnnotationsAction_ = nullptr;
  QAction* inferTextureAction_ = nullptr;
  QAction* saveLogAction_ = nullptr;
  QAction* closeLogAction_ = nullptr;
  std::array<QAction*, 4> exportActions_{};
};

}  // namespace kerf
