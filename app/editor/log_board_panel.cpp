// LogBoardController: CLT, veneer and plywood from the open log (docs/editor.md, "Logs and boards"): the
// panel choice in the Board dock (widgets/panel_controls.hpp) and the "Panel" view, rendered in the
// background with core's renderPanel (the pictures of `kerf-cli render-panel`), a small preview first.
#include "document.hpp"
#include "image_pane.hpp"
#include "job_runner.hpp"
#include "log_board_controller.hpp"
#include "log_board_faces.hpp"
#include "panel_controls.hpp"
#include "qt_image.hpp"

namespace kerf {

namespace {
constexpr int kPanelPreviewPixels = 300, kPanelPixels = 1200;
}

void LogBoardController::showPanel(const PanelOptions& options) {
  if (!document_->log()) return;
  showDock("panelDock");
  if (panelJob_ && jobs_->isRunning(panelJob_)) jobs_->cancel(panelJob_);
  const LogModel log = document_->log()->log;
  const WoodParameters params = document_->project().params;
  const auto show = [this](const QVariant& result) {
    const auto [image, caption] = result.value<std::pair<QImage, QString>>();
    views_.panelPane->setImage(image, caption);
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
