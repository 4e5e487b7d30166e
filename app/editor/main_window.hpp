#pragma once
// The editor's main window: the six faces unfolded next to the live 3D block, the parameter panel, the
// cut plane (3D gizmo, numeric controls and a true-scale cut panel), the log and the undo history.
// Every edit goes through the Document (undoable); every long task through the JobRunner (progress,
// cancel, never on the GUI thread).
#include <QMainWindow>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "document_jobs.hpp"
#include "export_dialog.hpp"
#include "fit_job.hpp"
#include "texture/texture_inference.hpp"
#include "texture_job.hpp"

class QAction;
class QActionGroup;
class QMenu;
class QLabel;
class QSlider;
class QSplitter;
class QStackedWidget;
class QToolBar;
class QUndoView;

class QTabWidget;

namespace kerf {

class AnnotationLayer;
class Autosave;
class BoardControls;
class KnotTable;
class LogView;
struct KnotShape;
struct LogModel;
struct BoardWood;
class ImagePane;
class PanelControls;
struct PanelOptions;
class CutPlaneControls;
class CutView;
class Document;
class FacesView;
class JobRunner;
class LogPanel;
class ParameterPanel;
class PartExportDialog;
class RecentFiles;
class Viewport3D;
class WindowLayout;
class WorkPath;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(RenderSettings settings = {}, QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a .kerf project or a sample folder (in the background); the current document stays open
  // until the new one has loaded, and stays if loading fails.
  void openDocument(const QString& path);
  // Generates the demo into `folder` if it is not there yet, then opens it.
  void openDemo(const QString& folder, const DemoOptions& options = demoOptions());
  static DemoOptions demoOptions();  // what the editor's demo uses: 256 px faces

  // Saves to the document's file (or asks for one); returns false if nothing was saved.
  bool save();
  bool saveAs(QString path = {});
  // Offers to recover the copies an earlier session's autosave left behind (asks the user).
  void offerRecovery();
  // Opens an autosave copy as a modified document attached to its original file.
  void recover(const QString& autosaveFile);
  // While false (tests), closing a modified document discards it without asking.
  void setAskBeforeDiscarding(bool ask) { askBeforeDiscarding_ = ask; }

  bool isBusy() const;
  bool hasDocument() const { return hasDocument_; }
  bool showingPhotos() const;
  QString documentName() const;
  QString lastError() const { return lastError_; }

  Document* document() const { return document_; }
  FacesView* facesView() const { return facesView_; }
  Viewport3D* viewport() const { return viewport_; }
  CutView* cutView() const { return cutView_; }
  ParameterPanel* parameterPanel() const { return parameterPanel_; }
  CutPlaneControls* cutControls() const { return cutControls_; }
  JobRunner* jobs() const { return jobs_; }
  LogPanel* log() const { return log_; }
  Autosave* autosave() const { return autosave_; }
  QAction* toggleViewAction() const { return toggleViewAction_; }
  WindowLayout* windowLayout() const { return layout_; }
  // The start page, Open Photos, Reconstruct and the fit's quality in the status bar (work_path.hpp).
  WorkPath* workPath() const { return workPath_; }
  // Photos, Model, Blend, Split, Difference (FaceDisplay order; Ctrl+1 .. Ctrl+5), and the slider of Blend
  // (opacity) and Split (where the line lies).
  QList<QAction*> faceDisplayActions() const;
  QSlider* faceSlider() const { return blendSlider_; }
  QAction* undoAction() const { return undoAction_; }
  QAction* redoAction() const { return redoAction_; }

  // Rings menu. Detect Rings runs the ring detector on every face photo (a job); the ring-localization
  // images and contours are kept here, with the window, not in the project file, and the contours
  // are drawn over the faces (View > Show Ring Contours). Fit Growth Field fits the growth field to
  // the detected images (or to the sample folder's own X_arl*.png when nothing was detected) and
  // applies it as one undo step.
  void detectRings();
  void fitGrowthField();
  // File > Import Photos (main_window_import.cpp): the dialog on `files` (a file chooser first when
  // empty), then the faces written in the background and applied as one undo step (photosImported()).
  void importPhotos(const QStringList& files = {});
  QAction* importPhotosAction() const { return importPhotosAction_; }
  // Null before a detection, and after the photos change.
  std::shared_ptr<const RingDetection> ringDetection() const { return ringDetection_; }
  QAction* detectRingsAction() const { return detectRingsAction_; }
  QAction* fitGrowthAction() const { return fitGrowthAction_; }
  // After an ambiguous fit (Mokume B.1): swaps the field for the one around the other pith candidate.
  QAction* otherPithAction() const { return otherPithAction_; }
  QAction* showResidualsAction() const { return showResidualsAction_; }
  QAction* showContoursAction() const { return showContoursAction_; }
  // Ring tracing (main_window_annotations.cpp): the tools over the faces view; detected contours become
  // the document's Detected traces (one undo step); the annotations export as Mokume images into
  // `folder` (asked for when empty). Returns false (with a message) when nothing was written.
  AnnotationLayer* annotationLayer() const { return annotationLayer_; }
  bool exportAnnotations(QString folder = {});
  QAction* exportAnnotationsAction() const { return exportAnnotationsAction_; }

  // Texture menu (main_window_texture.cpp): Infer Texture from Photos runs the texture inference of
  // `kerf-cli texture` on the document's photos and fitted field (a job with live preview, cancellable) and
  // applies the result as one undo step. The options are the core's defaults unless set (tests: smaller).
  void inferTexture();
  QAction* inferTextureAction() const { return inferTextureAction_; }
  void setTextureOptions(const TextureInferenceOptions& options) { textureOptions_ = options; }

  // Logs (main_window_log.cpp): a .kerflog file or Gran_1 folder (read in the background), or a random
  // log; attached to the document as one undo step (a new document when none is open), with the default
  // flat-sawn board. The faces then show the board. Save Log As writes the log alone (asks when empty).
  void openLog(const QString& path);
  void openRandomLog(std::uint32_t seed);
  bool saveLogAs(QString path = {});
  void closeLog();
  LogView* logView() const { return logView_; }
  BoardControls* boardControls() const { return boardControls_; }
  KnotTable* knotTable() const { return knotTable_; }
  // CLT, veneer or plywood from the open log, rendered in the background into the Panel view.
  void showPanel(const PanelOptions& options);
  PanelControls* panelControls() const { return panelControls_; }
  ImagePane* panelPane() const { return panelPane_; }

  // File > Export (main_window_export.cpp): Face Image, Cut Image (the document's cut plane), Volume and
  // Depth Stack open an ExportDialog (returned, non-modal); its request runs as a background job
  // (startExport, also for tests), ending in exportFinished or exportFailed (with a message box).
  ExportDialog* showExportDialog(ExportDialog::Kind kind);
  int startExport(const ExportRequest& request);
  // File > Export > Part… (main_window_export.cpp): modeless; the placed part shows in the 3D view while
  // it is open.
  PartExportDialog* showPartExportDialog();
  QAction* exportAction(ExportDialog::Kind kind) const { return exportActions_[static_cast<int>(kind)]; }

 signals:
  // An export job wrote its file(s) (message: what was written), or failed / was cancelled.
  void exportFinished(const QString& path, const QString& message);
  void exportFailed(const QString& message);
  // A log is attached (its faces follow with facesPreviewed / facesRendered).
  void logOpened();
  // A panel (showPanel) is shown at full resolution.
  void panelRendered();
  // A document was opened from `path` (a .kerf file or a folder of photos) and is now the document.
  void documentOpened(const QString& path);
  // The document has loaded and its faces have rendered (at full resolution).
  void documentReady();
  // Loading failed; the message is also shown in a (non-blocking) message box and the log.
  void documentFailed(const QString& message);
  // The model's faces were rendered again after an edit (full resolution).
  void facesRendered();
  // A quicker, coarser rendering of the faces is on screen (before facesRendered).
  void facesPreviewed();
  // Detect Rings / Fit Growth Field finished and their result is shown / applied.
  void ringsDetected();
  void growthFieldFitted();
  // The fit's live preview (the undeformed field after the pith stage, then the result) is on screen.
  void fitPreviewed();
  // Either of them failed (the message is also in the log and a message box) or was cancelled.
  void ringJobFailed(const QString& message);
  void photosImported();
  // Infer Texture finished and its result is applied / an improved texture is previewed on the faces /
  // it failed or was cancelled (the message is also in the log and, for errors, a message box).
  void textureInferred();
  void texturePreviewed();
  void textureJobFailed(const QString& message);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  friend class WorkPath;  // the path through the work drives the rings, fit and texture steps
  void createViews();
  void createDocks();
  void createMenus();
  void createRingsMenu();
  void createTextureMenu();  // main_window_texture.cpp
  void showTexturePreview(const WoodParameters& params);
  // Results that have landed (from their own action or from Reconstruct), applied as one undo step each;
  // false (with a message) when the result is not valid.
  void showRingDetection(std::shared_ptr<const RingDetection> detection);
  bool applyFit(std::shared_ptr<const GrowthFitResult> fit);
  bool applyTexture(std::shared_ptr<const TextureJobResult> texture);
  QAction* createImportAction();  // main_window_import.cpp
  void createLogDocks();          // main_window_log.cpp
  void createLogActions(QMenu* file);
  void chooseLog();
  void attachLog(LogModel log);
  void showLog();
  void renderBoardFaces();
  // The board's wood for the 3D view and the cut panel (GLSL, per fragment); `logOrParameters`: the
  // knot field and the colour map are rebuilt, otherwise only the board moved.
  void updateBoardWood(bool logOrParameters);
  void addKnot();
  void deleteKnot(int knot);
  void editKnot(int knot, const KnotShape& shape);
  void createPanelDock(QTabWidget* boardTabs);  // main_window_panel.cpp
  void clearRingDetection();
  QToolBar* createAnnotationBar(QWidget* parent);
  void applyDetectedTraces(const RingDetection& detection);
  void ringJobEnded(int id, const QString& message);
  void connectDocument();

  void chooseDocument();
  void startLoad(const QString& what, std::function<LoadedDocument(const Progress&)> load);
  void documentLoaded(const LoadedDocument& loaded);
  bool maybeSave();  // false: the user cancelled

  void modelChanged();
  void renderFaces();
  void renderFacesOf(std::shared_ptr<const WoodModel> model);
  void showFitPreview(const WoodParameters& params, const GrowthRates& rates);
  void showFitResiduals(const GrowthFitResult& fit);
  void useOtherPithCandidate();
  void updateFacesView();
  void updateFaceSlider();
  void setFaceDisplay(int display);
  void toggleView();
  void dropPhoto(FaceId face, const QString& path);
  void applyPreset(const QString& presetId);

  void exportFaces();
  void createExportActions(QMenu* exportMenu);  // main_window_export.cpp

  void showError(const QString& message);
  void logMessage(const QString& level, const QString& text);
  void updateTitle();

  RenderSettings settings_;
  Document* document_ = nullptr;
  JobRunner* jobs_ = nullptr;
  Autosave* autosave_ = nullptr;
  RecentFiles* recent_ = nullptr;
  bool hasDocument_ = false;
  bool documentReadyPending_ = false;
  bool askBeforeDiscarding_ = true;
  QString lastError_;
  std::array<QImage, 6> renderings_;
  int displayMode_ = 0;  // FaceDisplay as int
  bool displayChosenByUser_ = false;
  int renderJob_ = 0;
  int ringJob_ = 0, fitJob_ = 0;
  int importJob_ = 0;
  int textureJob_ = 0;
  QAction* inferTextureAction_ = nullptr;
  TextureInferenceOptions textureOptions_;
  std::shared_ptr<const RingDetection> ringDetection_;

  WindowLayout* layout_ = nullptr;
  WorkPath* workPath_ = nullptr;
  QStackedWidget* facesStack_ = nullptr;  // the start page, then the faces
  QSplitter* centralSplitter_ = nullptr;  // the faces | 3D block
  FacesView* facesView_ = nullptr;
  Viewport3D* viewport_ = nullptr;
  CutView* cutView_ = nullptr;
  ParameterPanel* parameterPanel_ = nullptr;
  CutPlaneControls* cutControls_ = nullptr;
  LogPanel* log_ = nullptr;
  QUndoView* history_ = nullptr;
  QSlider* blendSlider_ = nullptr;
  QLabel* cursorLabel_ = nullptr;
  QLabel* documentLabel_ = nullptr;
  QActionGroup* displayGroup_ = nullptr;
  QAction* toggleViewAction_ = nullptr;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* showPhotosOn3dAction_ = nullptr;
  QAction* detectRingsAction_ = nullptr;
  QAction* fitGrowthAction_ = nullptr;
  QAction* otherPithAction_ = nullptr;
  QAction* showResidualsAction_ = nullptr;
  std::shared_ptr<const GrowthFitResult> lastFit_;  // for the other pith candidate
  QAction* showContoursAction_ = nullptr;
  AnnotationLayer* annotationLayer_ = nullptr;
  QAction* exportAnnotationsAction_ = nullptr;
  QAction* importPhotosAction_ = nullptr;
  LogView* logView_ = nullptr;
  BoardControls* boardControls_ = nullptr;
  KnotTable* knotTable_ = nullptr;
  std::array<QAction*, 4> exportActions_{};
  std::vector<int> exportJobs_;
  QAction* saveLogAction_ = nullptr;
  QAction* closeLogAction_ = nullptr;
  bool logShown_ = false;                       // the views show a log (its board's faces)
  std::shared_ptr<const BoardWood> boardWood_;  // what the 3D view and the cut panel show in log mode
  int boardWoodJob_ = 0;                        // the knot field being made in the background
  PanelControls* panelControls_ = nullptr;
  ImagePane* panelPane_ = nullptr;
  int panelJob_ = 0;
};

}  // namespace kerf
