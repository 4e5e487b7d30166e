#pragma once
// The editor's texture inference, run off the GUI thread as a JobRunner job: the detail of the wood
// (pores, rays, fibres, early-to-late transition) and its colours from the face photos, given the fitted
// growth field (inferTexture, the pipeline of `kerf-cli texture`, core/texture/texture_inference.hpp).
// A self-contained function of values: no QObject, no shared state.
#include <QImage>
#include <QStringList>
#include <array>
#include <functional>

#include "field/growth_rates.hpp"
#include "geometry/block.hpp"
#include "params/parameter_schema.hpp"
#include "texture/texture_inference.hpp"
#include "util/progress.hpp"

namespace kerf {

struct TextureJobResult {
  WoodParameters params;  // the input with the inferred detail (and refitted colours) replaced
  QStringList report;     // lines for the log: per face orientation and distances, losses, timings
  double lossBefore = 0, lossAfter = 0;
};

// Called from the job's thread with every improved parameter set, for the live preview.
using TexturePreview = std::function<void(const WoodParameters&)>;

// Throws InputError (no photos, photos whose proportions differ from their faces), Cancelled on request.
TextureJobResult inferTextureFromPhotos(const Block& block, const WoodParameters& current,
                                        const GrowthRates& rates, const std::array<QImage, 6>& photos,
                                        const TextureInferenceOptions& options, const Progress& progress = {},
                                        const TexturePreview& preview = {});

}  // namespace kerf
