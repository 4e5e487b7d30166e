#pragma once
// The editor's main window. For now: open a document (project or sample folder) and show its six
// faces, as photos or as the model's rendering. Loading and rendering run on a private thread pool;
// the GUI thread only starts jobs and takes their results.
#include <QMainWindow>
#include <QThreadPool>
#include <atomic>
#include <functional>
#include <memory>
#include <stop_token>

#include "document_jobs.hpp"

class QAction;
class QLabel;
class QProgressBar;
class QTimer;

namespace kerf {

class FacesView;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(RenderSettings settings = {}, QWidget* parent = nullptr);
  ~MainWindow() override;

  // Start loading; the current document stays until the new one has loaded.
  void openDocument(const QString& path);
  // Generates the demo into `folder` if it is not there yet, then opens it.
  void openDemo(const QString& folder, const DemoOptions& options = demoOptions());
  static DemoOptions demoOptions();  // what the editor's demo uses: 256 px faces

  // State, for the status bar, the command line and tests.
  bool isBusy() const { return busy_; }
  bool hasDocument() const { return document_.model != nullptr; }
  bool showingPhotos() const;
  QString documentName() const { return document_.name; }
  QString lastError() const { return lastError_; }
  FacesView* facesView() const { return facesView_; }
  QAction* toggleViewAction() const { return toggleViewAction_; }

 signals:
  // The document has loaded and its faces have rendered.
  void documentReady();
  // Loading or rendering failed; the message is also shown in a (non-blocking) message box.
  void documentFailed(const QString& message);

 private:
  void createMenus();
  void chooseDocument();
  void startLoad(const QString& what, std::function<LoadedDocument(const Progress&)> load);
  void documentLoaded(const LoadedDocument& document);
  void startRendering();
  void facesRendered(const RenderedFaces& faces);
  void showError(const QString& message);
  void toggleView();
  void updateView();
  void updateStatus();
  Progress startJob(const QString& message);  // cancels the running job, returns the new job's Progress
  void finishJob();

  RenderSettings settings_;
  LoadedDocument document_;
  std::array<QImage, 6> renderings_;
  bool preferPhotos_ = true;
  bool busy_ = false;
  QString busyMessage_;
  QString lastError_;

  // Jobs: each gets a generation number; results of superseded jobs are dropped.
  int generation_ = 0;
  std::stop_source stop_;
  std::shared_ptr<std::atomic<double>> progress_;
  QThreadPool pool_;

  FacesView* facesView_ = nullptr;
  QAction* toggleViewAction_ = nullptr;
  QLabel* statusLabel_ = nullptr;
  QProgressBar* progressBar_ = nullptr;
  QTimer* progressTimer_ = nullptr;
};

}  // namespace kerf
