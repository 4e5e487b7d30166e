#pragma once
// The path through the work (issue 20 item 2), a controller of the main window: the start page while no
// document is open (photos, project, demo, recent files); the photos on the 3D block as soon as they are
// loaded, until a field is fitted; one Reconstruct action (rings > growth field > appearance, one
// background job of named stages, each stage's result shown as it lands: the rings on the faces, then the
// field, then the wood), ending on the cut; and the fit's quality in words in the status bar (item 3).
#include <QObject>
#include <cstdint>
#include <optional>

#include "reconstruct_job.hpp"

class QAction;
class QLabel;
class QStackedWidget;
class QToolBar;

namespace kerf {

class MainWindow;
class StartPage;

class WorkPath : public QObject {
  Q_OBJECT

 public:
  // `facesStack` holds the faces pane; the start page is added to it.
  WorkPath(MainWindow* window, QStackedWidget* facesStack);

  StartPage* startPage() const { return startPage_; }
  bool showingStartPage() const;
  QAction* reconstructAction() const { return reconstructAction_; }
  QAction* openPhotosAction() const { return openPhotosAction_; }
  QToolBar* toolBar() const { return toolBar_; }
  // The fit's quality in words; while Reconstruct runs, its stage and progress.
  QLabel* fitLabel() const { return fitLabel_; }

  // Starts Reconstruct (refused with a message without photos or while other ring work runs); when it
  // runs already, stops it (what had landed stays).
  void reconstruct();
  void cancel();
  bool isRunning() const;
  // The appearance stage: the texture inference (the window's texture options), or none.
  void setInferAppearance(bool on) { inferAppearance_ = on; }
  // File > Open Photos: a folder of face photos (asked for when empty).
  void openPhotos(QString folder = {});

 signals:
  void stageStarted(kerf::ReconstructStage stage);
  void stageLanded(kerf::ReconstructStage stage);
  // Every stage has landed and the cut is shown.
  void reconstructed();
  // Refused, failed (the message is also in the log and a message box) or cancelled ("cancelled").
  void reconstructFailed(const QString& message);

 private:
  void onEvent(const ReconstructEvent& event);
  void finish();
  void ended(int id, const QString& message);
  void showPhotosOnBlock(bool on);
  void documentOpened(const QString& path);
  void updateActions();
  void updateFitLabel();
  void showStage(double fraction);

  MainWindow* window_;
  QStackedWidget* facesStack_;
  StartPage* startPage_;
  QAction* reconstructAction_;
  QAction* openPhotosAction_;
  QToolBar* toolBar_;
  QLabel* fitLabel_;
  int job_ = 0;
  QString stage_;  // the running stage's name
  bool inferAppearance_ = true;
  // What a later Reconstruct may reuse (issue 20 item 2; work_path_rerun.cpp).
  ReconstructState currentState() const;
  void annotationsEdited();
  bool annotationsChangedSinceFit_ = true;
  bool applyingDetection_ = false;                // Reconstruct's own detected traces are landing
  std::optional<std::uint64_t> appearanceField_;  // the field the wood was last inferred on
  bool photosOnBlockByUs_ = false;  // turned on for photos without a model: off again once one is fitted
};

}  // namespace kerf
