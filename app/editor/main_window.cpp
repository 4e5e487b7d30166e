#include "main_window.hpp"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QStatusBar>
#include <QTimer>
#include <QtConcurrent>
#include <type_traits>

#include "faces_view.hpp"

namespace kerf {

namespace {

const QString kRendering = QStringLiteral("Rendering faces…");

// Runs `work` on `pool` and hands its result to `done` on the GUI thread (the watcher lives in
// `owner`, so nothing is delivered once the window is gone).
template <class Work, class Done>
void runAsync(QObject* owner, QThreadPool* pool, Work work, Done done) {
  using Result = std::invoke_result_t<Work>;
  auto* watcher = new QFutureWatcher<Result>(owner);
  QObject::connect(watcher, &QFutureWatcher<Result>::finished, owner, [watcher, done] {
    done(watcher->result());
    watcher->deleteLater();
  });
  watcher->setFuture(QtConcurrent::run(pool, std::move(work)));
}

// The file dialog picks files, so a sample folder is opened by picking one of its face photos.
QString documentPathFor(const QString& chosen) {
  const QFileInfo info(chosen);
  return info.suffix().compare("kerf", Qt::CaseInsensitive) == 0 ? chosen : info.absolutePath();
}

}  // namespace

MainWindow::MainWindow(RenderSettings settings, QWidget* parent) : QMainWindow(parent), settings_(settings) {
  pool_.setMaxThreadCount(2);  // a new job may start while a cancelled one winds down
  facesView_ = new FacesView(this);
  setCentralWidget(facesView_);
  createMenus();

  statusLabel_ = new QLabel(this);
  progressBar_ = new QProgressBar(this);
  progressBar_->setRange(0, 100);
  progressBar_->setMaximumWidth(200);
  progressBar_->setVisible(false);
  statusBar()->addWidget(statusLabel_, 1);
  statusBar()->addPermanentWidget(progressBar_);
  // Workers store their progress in an atomic; the GUI polls it rather than receive an event per row.
  progressTimer_ = new QTimer(this);
  progressTimer_->setInterval(100);
  connect(progressTimer_, &QTimer::timeout, this, [this] {
    if (progress_) progressBar_->setValue(static_cast<int>(progress_->load() * 100));
  });

  setWindowTitle(QStringLiteral("Kerf"));
  resize(1280, 800);
  updateStatus();
}

MainWindow::~MainWindow() {
  stop_.request_stop();
  pool_.waitForDone();  // jobs stop at the next row; core must not outlive the application
}

DemoOptions MainWindow::demoOptions() {
  DemoOptions options;
  options.facePixels = 256;
  return options;
}

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(tr("&Open Project or Sample Folder…"), this, &MainWindow::chooseDocument);
  open->setShortcut(QKeySequence::Open);
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));

  QMenu* view = menuBar()->addMenu(tr("&View"));
  toggleViewAction_ = view->addAction(tr("Show &Model Rendering"), this, &MainWindow::toggleView);
  toggleViewAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
  toggleViewAction_->setEnabled(false);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About Kerf"), this, [this] {
    QMessageBox::about(this, tr("About Kerf"),
                       tr("<b>Kerf</b> %1<br>An editor for the procedural appearance of solid wood.")
                           .arg(QApplication::applicationVersion()));
  });
}

void MainWindow::chooseDocument() {
  const QString chosen = QFileDialog::getOpenFileName(
      this, tr("Open a project, or any face photo of a sample folder"), QString(),
      tr("Projects and face photos (*.kerf *_col.png *_col.jpg *_col.jpeg *_col.tif *_col.tiff);;"
         "Kerf projects (*.kerf);;All files (*)"));
  if (!chosen.isEmpty()) openDocument(documentPathFor(chosen));
}

void MainWindow::openDocument(const QString& path) {
  startLoad(tr("Loading %1…").arg(QFileInfo(path).fileName()),
            [path](const Progress&) { return loadDocumentFiles(path); });
}

void MainWindow::openDemo(const QString& folder, const DemoOptions& options) {
  startLoad(tr("Preparing the demo…"),
            [folder, options](const Progress& progress) { return loadDemo(folder, options, progress); });
}

Progress MainWindow::startJob(const QString& message) {
  stop_.request_stop();
  stop_ = std::stop_source();
  ++generation_;
  progress_ = std::make_shared<std::atomic<double>>(0.0);
  busy_ = true;
  busyMessage_ = message;
  facesView_->setPlaceholderText(message);  // seen only while there is nothing else to show
  progressBar_->setValue(0);
  progressTimer_->start();
  updateStatus();
  return Progress{[p = progress_](double f) { p->store(f, std::memory_order_relaxed); }, stop_.get_token()};
}

void MainWindow::finishJob() {
  busy_ = false;
  progressTimer_->stop();
  updateStatus();
}

void MainWindow::startLoad(const QString& what, std::function<LoadedDocument(const Progress&)> load) {
  const Progress progress = startJob(what);
  const int generation = generation_;
  runAsync(
      this, &pool_, [load, progress] { return load(progress); },
      [this, generation](const LoadedDocument& document) {
        if (generation == generation_) documentLoaded(document);
      });
}

void MainWindow::documentLoaded(const LoadedDocument& document) {
  if (!document.ok()) {
    finishJob();
    // Starting the load cancelled the current document's rendering; resume it.
    if (hasDocument() && renderings_[0].isNull()) startRendering();
    showError(document.error);
    return;
  }
  document_ = document;
  renderings_ = {};
  preferPhotos_ = true;
  setWindowTitle(tr("%1 — Kerf").arg(document_.name));
  updateView();
  startRendering();
}

void MainWindow::startRendering() {
  const Progress progress = startJob(kRendering);
  const int generation = generation_;
  runAsync(
      this, &pool_,
      [model = document_.model, settings = settings_, progress] {
        return renderModelFaces(*model, settings, progress);
      },
      [this, generation](const RenderedFaces& faces) {
        if (generation == generation_) facesRendered(faces);
      });
}

void MainWindow::facesRendered(const RenderedFaces& faces) {
  finishJob();
  if (faces.cancelled) return;
  if (!faces.error.isEmpty()) {
    facesView_->setPlaceholderText(tr("The faces could not be rendered."));
    showError(faces.error);
    return;
  }
  renderings_ = faces.faces;
  updateView();
  emit documentReady();
}

void MainWindow::showError(const QString& message) {
  lastError_ = message;
  // open() is window-modal but returns at once: the GUI thread never blocks on the user.
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Kerf"), message, QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
  emit documentFailed(message);
}

bool MainWindow::showingPhotos() const {
  return preferPhotos_ && document_.hasPhotos();
}

void MainWindow::toggleView() {
  preferPhotos_ = !preferPhotos_;
  updateView();
}

void MainWindow::updateView() {
  const bool renderingsReady = !renderings_[0].isNull();
  if (showingPhotos()) {
    facesView_->setFaces(document_.photos, document_.project->block);
  } else if (renderingsReady) {
    facesView_->setFaces(renderings_, document_.project->block);
  } else {
    facesView_->clear();
  }
  toggleViewAction_->setEnabled(document_.hasPhotos());
  toggleViewAction_->setText(showingPhotos() ? tr("Show &Model Rendering") : tr("Show &Photos"));
  const QString shortcut = toggleViewAction_->shortcut().toString(QKeySequence::NativeText);
  if (!hasDocument()) {
    facesView_->setCaption({});
  } else if (showingPhotos()) {
    facesView_->setCaption(tr("Photos"), tr("%1 shows the model rendering").arg(shortcut));
  } else {
    facesView_->setCaption(tr("Model rendering"),
                           document_.hasPhotos() ? tr("%1 shows the photos").arg(shortcut) : QString());
  }
  updateStatus();
}

void MainWindow::updateStatus() {
  progressBar_->setVisible(busy_);
  if (busy_) {
    statusLabel_->setText(busyMessage_);
    return;
  }
  if (!hasDocument()) {
    statusLabel_->setText(tr("No document"));
    return;
  }
  const glm::vec3 size = document_.project->block.size();
  statusLabel_->setText(tr("%1 — block %2 × %3 × %4 mm — %5")
                            .arg(document_.name)
                            .arg(size.x, 0, 'g', 4)
                            .arg(size.y, 0, 'g', 4)
                            .arg(size.z, 0, 'g', 4)
                            .arg(showingPhotos() ? tr("photos") : tr("model rendering")));
}

}  // namespace kerf
