// MainWindow: the ring-tracing tools of the faces view (widgets/annotation_layer.hpp), detected
// contours taken over as editable traces, and the export of the annotations in the Mokume format.
#include <QAction>
#include <QFileDialog>
#include <QStatusBar>
#include <QToolBar>

#include "annotation_layer.hpp"
#include "document.hpp"
#include "faces_view.hpp"
#include "io/mokume_annotation_files.hpp"
#include "main_window.hpp"
#include "rings/annotations.hpp"
#include "rings/contours.hpp"
#include "util/error.hpp"

namespace kerf {

QToolBar* MainWindow::createAnnotationBar(QWidget* parent) {
  annotationLayer_ = new AnnotationLayer(facesView_);
  auto* bar = new QToolBar(tr("Ring Tracing"), parent);
  bar->setObjectName("ringTracingBar");
  bar->setIconSize(QSize(16, 16));
  bar->setStyleSheet(QStringLiteral("QToolButton { padding: 1px 3px; }"));  // ten buttons in half a window
  bar->addActions(annotationLayer_->toolActions());
  bar->addSeparator();
  bar->addActions(annotationLayer_->editActions());
  connect(annotationLayer_, &AnnotationLayer::edited, this,
          [this](const Annotations& after, const QString& text) { document_->editAnnotations(after, text); });
  connect(annotationLayer_, &AnnotationLayer::message, this,
          [this](const QString& text) { statusBar()->showMessage(text, 8000); });
  connect(document_, &Document::annotationsChanged, this, [this] {
    annotationLayer_->setAnnotations(document_->annotations());
    if (showContoursAction_)
      showContoursAction_->setEnabled(!document_->annotations().empty() || ringDetection_);
    if (exportAnnotationsAction_) exportAnnotationsAction_->setEnabled(!document_->annotations().empty());
  });
  exportAnnotationsAction_ = new QAction(tr("Export &Mokume Annotations…"), this);
  exportAnnotationsAction_->setToolTip(
      tr("Write the numbered ring traces (X_ann.png: pixel = year) and knot marks (X_knot.png) in the Mokume "
         "sample format, at the size of the face photos"));
  exportAnnotationsAction_->setEnabled(false);
  connect(exportAnnotationsAction_, &QAction::triggered, this, [this] { exportAnnotations(); });
  return bar;
}

void MainWindow::applyDetectedTraces(const RingDetection& detection) {
  std::vector<RingTrace> traces = detectedRingTraces(detection, document_->project().block);
  const int count = static_cast<int>(traces.size());
  document_->editAnnotations(replaceDetectedTraces(document_->annotations(), std::move(traces)),
                             tr("Detect rings (%n traces)", "", count));
}

bool MainWindow::exportAnnotations(QString folder) {
  const Annotations& annotations = document_->annotations();
  const bool numbered = std::any_of(annotations.traces.begin(), annotations.traces.end(),
                                    [](const RingTrace& t) { return t.year.has_value(); });
  if (!numbered && annotations.knots.empty()) {
    showError(
        tr("There is nothing to export in the Mokume format: it holds ring traces numbered by year and "
           "knot marks. Select traces and number them with N first."));
    return false;
  }
  if (folder.isEmpty()) {
    folder = QFileDialog::getExistingDirectory(this, tr("Folder for the Mokume annotation images"));
    if (folder.isEmpty()) return false;
  }
  std::array<glm::ivec2, 6> sizes;
  for (FaceId face : kAllFaces) {
    const QImage& photo = document_->photos()[faceIndex(face)];
    sizes[faceIndex(face)] = photo.isNull() ? mokumeImageSize(document_->project().block, face)
                                            : glm::ivec2(photo.width(), photo.height());
  }
  try {
    const auto written =
        writeMokumeAnnotations(annotations, document_->project().block, folder.toStdString(), sizes);
    QStringList names;
    for (const auto& file : written) names << QString::fromStdString(file.filename().string());
    const int unnumbered = static_cast<int>(std::count_if(
        annotations.traces.begin(), annotations.traces.end(), [](const RingTrace& t) { return !t.year; }));
    logMessage("info",
               tr("Mokume annotations written to %1: %2%3")
                   .arg(folder, names.join(", "),
                        unnumbered ? tr(" (%n unnumbered trace(s) left out)", "", unnumbered) : QString()));
    return true;
  } catch (const InputError& e) {
    showError(tr("The annotations could not be exported: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
}

}  // namespace kerf
