// RingsController: the ring traces edited with the tools of the faces view (widgets/annotation_layer.hpp),
// detected contours taken over as editable traces, and the export of the annotations in the Mokume format.
#include <QAction>
#include <QFileDialog>

#include "annotation_layer.hpp"
#include "document.hpp"
#include "io/mokume_annotation_files.hpp"
#include "rings/annotations.hpp"
#include "rings/contours.hpp"
#include "rings_controller.hpp"
#include "util/error.hpp"

namespace kerf {

// The traces changed (an edit, an undo, another document): the tools and the actions follow.
void RingsController::annotationsChanged() {
  annotationLayer_->setAnnotations(document_->annotations());
  if (actions_.showContours)
    actions_.showContours->setEnabled(!document_->annotations().empty() || ringDetection_);
  if (actions_.exportAnnotations) actions_.exportAnnotations->setEnabled(!document_->annotations().empty());
}

void RingsController::applyDetectedTraces(const RingDetection& detection) {
  std::vector<RingTrace> traces = detectedRingTraces(detection, document_->project().block);
  const int count = static_cast<int>(traces.size());
  document_->editAnnotations(replaceDetectedTraces(document_->annotations(), std::move(traces)),
                             tr("Detect rings (%n traces)", "", count));
}

bool RingsController::exportAnnotations(QString folder) {
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
    folder = QFileDialog::getExistingDirectory(window_, tr("Folder for the Mokume annotation images"));
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
    log("info", tr("Mokume annotations written to %1: %2%3")
                    .arg(folder, names.join(", "),
                         unnumbered ? tr(" (%n unnumbered trace(s) left out)", "", unnumbered) : QString()));
    return true;
  } catch (const InputError& e) {
    showError(tr("The annotations could not be exported: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
}

}  // namespace kerf
