#include "reconstruct_job.hpp"

#include <functional>

#include "geometry/face_set.hpp"

namespace kerf {
namespace {

// Shares of the progress bar: the appearance takes longest (minutes with the core's defaults).
constexpr double kRingsEnd = 0.1, kFieldEnd = 0.4;

// Stage 2: the growth field fitted to the traces (the detected ones and the user's own).
std::shared_ptr<const GrowthFitResult> fitField(const ReconstructInput& input,
                                                const std::shared_ptr<const RingDetection>& rings,
                                                const Annotations& annotations,
                                                const std::array<QImage, 6>& photos, const Progress& progress,
                                                const std::function<void(ReconstructEvent)>& send) {
  ReconstructEvent started;
  started.stage = ReconstructStage::Field;
  started.started = true;
  send(started);
  const GrowthFitPreview fieldPreview = [&send](const WoodParameters& params, const GrowthRates& rates) {
    ReconstructEvent event;
    event.stage = ReconstructStage::Field;
    event.fieldPreview = std::make_shared<const std::pair<WoodParameters, GrowthRates>>(params, rates);
    send(event);
  };
  const auto field = std::make_shared<const GrowthFitResult>(
      fitGrowthField(rings->arl, input.block, input.params, photos,
                     progress.part(kRingsEnd, input.inferAppearance ? kFieldEnd : 1.0), annotations.traces,
                     fieldPreview, annotations.knots, input.heldOut));
  ReconstructEvent event;
  event.stage = ReconstructStage::Field;
  event.field = field;
  send(event);
  return field;
}

}  // namespace

ReconstructPlan planReconstruct(const ReconstructState& state, bool inferAppearance) {
  ReconstructPlan plan;
  plan.detect = !state.ringsCurrent;
  plan.fit = plan.detect || !state.fieldCurrent;
  plan.infer = inferAppearance && (plan.fit || !state.appearanceCurrent);
  return plan;
}

void reconstructFromPhotos(const ReconstructInput& input, const Progress& progress,
                           const ReconstructEvents& events) {
  const auto send = [&events](ReconstructEvent event) {
    if (events) events(event);
  };
  const auto start = [&send](ReconstructStage stage) {
    ReconstructEvent event;
    event.stage = stage;
    event.started = true;
    send(event);
  };

  // 1. The rings on every photo but the held-out ones; they become the document's detected traces.
  std::array<QImage, 6> photos = input.photos;
  clearFaces(photos, input.heldOut);
  std::shared_ptr<const RingDetection> rings = input.rings;
  Annotations annotations = input.annotations;  // reused rings: the traces as the user left them
  if (!rings) {
    start(ReconstructStage::Rings);
    rings = std::make_shared<const RingDetection>(
        detectRings(photos, input.block, input.detector, progress.part(0.0, kRingsEnd)));
    ReconstructEvent event;
    event.stage = ReconstructStage::Rings;
    event.rings = rings;
    send(event);
    annotations = replaceDetectedTraces(input.annotations, detectedRingTraces(*rings, input.block));
  }
  progress.throwIfCancelled();

  // 2. The growth field, fitted to those traces (and the user's own) as Fit Growth Field does.
  // A reused field is the document's: its parameters, with the user's later edits, start the appearance.
  const bool reusedField = input.rings && input.field;
  std::shared_ptr<const GrowthFitResult> field = reusedField ? input.field : nullptr;
  if (!field) field = fitField(input, rings, annotations, photos, progress, send);
  if (!input.inferAppearance) return;
  progress.throwIfCancelled();

  // 3. The wood's appearance: pores, rays, fibres and colours from the photos, on the fitted field.
  start(ReconstructStage::Appearance);
  TextureInferenceOptions options = input.appearance;
  options.heldOut = input.heldOut;
  const TexturePreview appearancePreview = [&send](const WoodParameters& params) {
    ReconstructEvent event;
    event.stage = ReconstructStage::Appearance;
    event.appearancePreview = std::make_shared<const WoodParameters>(params);
    send(event);
  };
  ReconstructEvent landed;
  landed.stage = ReconstructStage::Appearance;
  landed.appearance = std::make_shared<const TextureJobResult>(
      inferTextureFromPhotos(input.block, reusedField ? input.params : field->params, field->rates, photos,
                             options, progress.part(kFieldEnd, 1.0), appearancePreview));
  send(landed);
}

}  // namespace kerf
