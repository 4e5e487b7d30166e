// WorkPath: after a correction, Reconstruct re-runs only what depends on it (issue 20 item 2). The rings
// are detected again only for new photos (or another set of held-out faces); the field is refitted when a
// ring trace or knot mark changed, or the document's field is no longer the last fit's; the wood is
// inferred again when the field it was inferred on is no longer the document's.
#include <QStatusBar>

#include "document.hpp"
#include "field/ring_uncertainty.hpp"
#include "main_window.hpp"
#include "rings_controller.hpp"
#include "work_path.hpp"

namespace kerf {

namespace {

std::uint64_t documentField(const Project& project) {
  return fieldFingerprint(project.params, project.effectiveRates(), project.knots);
}

// A detection of these photos: every face with a photo that is not held out has its ring image, and no
// held-out face has one.
bool detectionMatches(const RingDetection& rings, const Document& document) {
  const FaceSet& heldOut = document.project().heldOutFaces;
  for (FaceId face : kAllFaces) {
    const int i = faceIndex(face);
    const bool wanted = !document.photos()[i].isNull() && !heldOut.contains(face);
    if (wanted == rings.arl[i].empty()) return false;
  }
  return true;
}

}  // namespace

ReconstructState WorkPath::currentState() const {
  ReconstructState state;
  const Document& document = *window_->document();
  const auto rings = window_->rings()->ringDetection();
  // A detection by the other detector than the one now chosen is redone.
  state.ringsCurrent =
      rings && detectionMatches(*rings, document) && rings->detector == window_->rings()->detector();
  const auto fit = window_->rings()->lastFit();
  const std::uint64_t field = documentField(document.project());
  state.fieldCurrent = fit && !annotationsChangedSinceFit_ && document.project().rates &&
                       fieldFingerprint(fit->params, fit->rates, fit->knots) == field;
  state.appearanceCurrent = appearanceField_ && *appearanceField_ == field;
  return state;
}

// A trace or mark changed: the field is stale. Said once, where the user looks, when there is a field.
void WorkPath::annotationsEdited() {
  if (applyingDetection_) return;  // Reconstruct's own detected traces
  const bool hadField = !annotationsChangedSinceFit_ && window_->rings()->lastFit();
  annotationsChangedSinceFit_ = true;
  if (hadField)
    window_->statusBar()->showMessage(
        tr("Rings changed: Reconstruct (Ctrl+R) refits the field and the wood to them, keeping the rings as "
           "they are"),
        10000);
}

}  // namespace kerf
