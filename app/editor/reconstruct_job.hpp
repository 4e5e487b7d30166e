#pragma once
// The editor's Reconstruct: from the face photos to the wood in one background job of three named stages,
// the same steps as Detect Rings, Fit Growth Field and Infer Texture one after the other (and as
// `kerf-cli reconstruct`): the rings on each photo (detectBlockRings, Mokume Sec. 5.1), the growth field
// fitted to them (fitGrowthFieldToSample, Sec. 5.2), then the wood's appearance (inferTexture, Sec. 5.3.1).
// A function of values, run off the GUI thread: each stage's start, previews and result are handed to
// `events` as they come, so the window can show them while the next stage runs.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "fit_job.hpp"
#include "texture_job.hpp"

namespace kerf {

enum class ReconstructStage { Rings = 0, Field = 1, Appearance = 2 };
inline constexpr int kReconstructStages = 3;

struct ReconstructInput {
  Block block;
  WoodParameters params;  // what the fit starts from
  std::array<QImage, 6> photos;
  FaceSet heldOut;          // nothing of these faces' photos is used
  Annotations annotations;  // the user's own traces are kept and fitted with the detected ones; knot marks
  TextureInferenceOptions appearance;
  std::string detector = kDefaultEditorRingDetector;  // the ring detector (fit_job.hpp detectRings)
  bool inferAppearance = true;  // false: the procedural wood of the fit (its colours) is the appearance
  // Re-running after a correction (issue 20 item 2): what is still current is reused, not redone.
  // rings: the ring images of the current photos; detection is skipped and the document's traces, the
  // user's corrections included, are fitted as they are. field (with rings): the document's current
  // field; only the appearance is inferred on it.
  std::shared_ptr<const RingDetection> rings;
  std::shared_ptr<const GrowthFitResult> field;
};

// What is still current in a document, and so what a Reconstruct must redo (issue 20 item 2): a stage
// runs when its own result is stale or an earlier stage runs.
struct ReconstructState {
  bool ringsCurrent = false;       // a detection of the current photos (held-out faces left out)
  bool fieldCurrent = false;       // the document's field is the last fit's, no trace or mark changed since
  bool appearanceCurrent = false;  // the wood was inferred on the document's field
};
struct ReconstructPlan {
  bool detect = true, fit = true, infer = true;
  bool nothing() const { return !detect && !fit && !infer; }
};
ReconstructPlan planReconstruct(const ReconstructState& state, bool inferAppearance);

// One thing that happened, in order; exactly one of the pointers is set unless `started`.
struct ReconstructEvent {
  ReconstructStage stage = ReconstructStage::Rings;
  bool started = false;                                                        // the stage begins
  std::shared_ptr<const RingDetection> rings;                                  // Rings landed
  std::shared_ptr<const std::pair<WoodParameters, GrowthRates>> fieldPreview;  // Field, while fitting
  std::shared_ptr<const GrowthFitResult> field;                                // Field landed
  std::shared_ptr<const WoodParameters> appearancePreview;                     // Appearance, while inferring
  std::shared_ptr<const TextureJobResult> appearance;                          // Appearance landed
};

using ReconstructEvents = std::function<void(const ReconstructEvent&)>;

// Runs the three stages (the appearance only with inferAppearance; detection and fit not when `rings` and
// `field` are given). Throws InputError (no photos, too few
// rings to fit, ...) and Cancelled; what had landed before was already handed to `events`.
void reconstructFromPhotos(const ReconstructInput& input, const Progress& progress,
                           const ReconstructEvents& events);

}  // namespace kerf
