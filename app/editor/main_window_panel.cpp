// MainWindow: CLT, veneer and plywood from the open log (docs/editor.md, "Logs and boards"): the panel
// choice in the Board dock (widgets/panel_controls.hpp) and the "Panel" view, rendered in the background
// with core's renderPanel (the pictures of `kerf-cli render-panel`), a small preview first.
#include <QDockWidget>
#include <QTabWidget>
#include <QVBoxLayout>

#include "document.hpp"
#include "image_pane.hpp"
#include "job_runner.hpp"
#include "log_board_faces.hpp"
#include "main_window.hpp"
#include "panel_controls.hpp"
#include "qt_image.hpp"

namespace kerf {

namespace {
constexpr int kPanelPreviewPixels = 300, kPanelPixels = 1200;
}

void MainWindow::createPanelDock(QTabWidget* boardTabs) {
  auto* page = new QWidget(boardTabs);
  auto* layout = new QVBoxLayout(page);
  panelControls_ = new PanelControls(page);
  layout->addWidget(panelControls_);
  layout->addStretch(1);
  boardTabs->addTab(page, tr("Panel"));

  panelPane_ = new ImagePane(this);
  panelPane_->setPlaceholder(tr("Choose a panel in the Board dock and press Show Panel"));
  auto* dock = new QDockWidget(tr("Panel"), this);
  dock->setObjectName("panelDock");
  dock->setWidget(panelPane_);
  addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (auto* logViewDock = findChild<QDockWidget*>("logViewDock")) tabifyDockWidget(logViewDock, dock);
  dock->hide();  // shown with the first panel

  connect(panelControls_, &PanelControls::panelRequested, this, &MainWindow::showPanel);
  connect(jobs_, &JobRunner::jobFailed, this, [this](int id, const QString& message) {
    if (id != panelJob_) return;
    panelJob_ = 0;
    showError(tr("The panel could not be made: %1").arg(message));
  });
}

void MainWindow::showPanel(const PanelOptions& options) {
  if (!document_->log()) return;
  if (auto* dock = findChild<QDockWidget*>("panelDock")) {
    dock->show();
    dock->raise();
  }
  if (panelJob_ && jobs_->isRunning(panelJob_)) jobs_->cancel(panelJob_);
  const LogModel log = document_->log()->log;
  const WoodParameters params = document_->project().params;
  const auto show = [this](const QVariant& result) {
    const auto [image, caption] = result.value<std::pair<QImage, QString>>();
    panelPane_->setImage(image, caption);
  };
  panelJob_ = jobs_->start(
      tr("Rendering panel"),
      [log, params, options](const Progress& progress, const JobRunner::Preview& preview) -> QVariant {
        const KnotField field(log, KnotSettings::fromParameters(params));
        const WoodColorMap colors = logColorMap(log, params);
        const auto render = [&](int pixels, const Progress& stage) {
          PanelOptions o = options;
          o.resolution = pixels;
          const RenderedPanel panel = renderPanel(field, colors, o, stage);
          return QVariant::fromValue(
              std::make_pair(toQImage(panel.image), QString::fromStdString(panel.description)));
        };
        preview(render(kPanelPreviewPixels, Progress{nullptr, progress.stop}));
        return render(kPanelPixels, progress);
      },
      [this, show](const QVariant& result) {
        panelJob_ = 0;
        show(result);
        emit panelRendered();
      },
      show, false);
}

}  // namespace kerf
