#pragma once
// Texture inference (Mokume Sec. 5.3.1 / A.2.3, the step after the growth field; the authors never
// published its code): given the fitted growth field and colours, find the detail parameters - pores,
// rays, fibres, the early-to-late transition - that make the rendered faces look like the photos.
// 1. Coarse search: a 3 x 3 x 3 grid over the sizes of fibres, pores and rays (every length of a
//    feature scaled together, texture/detail_space.hpp), evaluated as one parallel batch, plus the point
//    of each feature's best mean factor ("main effects", less noisy than the single best point).
// 2. Continuous search over every detail parameter with a parallel compass search
//    (texture/pattern_search.hpp: the loss is not smooth in the parameters, so no gradients).
// 3. The colours for the new detail (pores and fibres change the mean pigment): either the colour fit
//    run again (fit/colour_fit.hpp) or only the face tints scaled to each photo's mean colour, whichever
//    lowers the loss more; neither when neither does.
// The loss (texture/texture_objective.hpp) compares each face with its own photo: the grain direction and
// the contrast a woodworker sees (texture/grain_view.hpp), style statistics of a fixed filter bank and a
// weak L1 colour term. Deterministic for a seed (crop placement), cancellable.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "field/growth_rates.hpp"
#include "geometry/block.hpp"
#include "geometry/face_set.hpp"
#include "io/image.hpp"
#include "params/parameter_schema.hpp"
#include "texture/face_crops.hpp"
#include "texture/pattern_search.hpp"
#include "texture/texture_objective.hpp"
#include "util/progress.hpp"

namespace kerf {

struct TextureInferenceOptions {
  TextureLossOptions loss;
  std::vector<std::string> parameters;  // detail coordinates searched (detail_space.hpp); empty: all
  // Off by default (2026-12-07, docs/texture.md "The coarse grid off by default"): on CN03, all faces and
  // held out, and from a wrong species' start it scored the same as the search alone, but halved the kuri
  // preset's pores; its one win, the synthetic block's ray spacing, came from rays thinner than a pixel.
  // `kerf-cli texture --coarse` turns it on.
  bool coarseSearch = false;
  std::vector<float> coarseFactors{0.5f, 1.0f, 2.0f};  // size multipliers of the grid, per feature
  // 4 sweeps: on CN03 (all faces and held out, three crop seeds) as good as 8 in about 2/3 of the time.
  PatternSearchOptions search{.maxSweeps = 4};
  bool refitColours = true;
  bool fullFaceReport = true;  // per-face distances on whole faces (else on the crops)
  // Live preview: called from the calling thread with every improved parameter set.
  std::function<void(const WoodParameters&)> preview;
  // Faces held out (leave-one-face-out, fit/held_out_faces.hpp): their photos are dropped before the
  // search and the colour step read them, and their tints are neutral.
  FaceSet heldOut;
};

struct FaceTextureReport {
  bool hasPhoto = false;
  FaceOrientation orientation;
  FaceTextureScore before, after;
};

struct TextureInferenceResult {
  FaceSet heldOut;        // faces whose photos were not used
  WoodParameters params;  // the input with the searched detail (and, refitted, colour) parameters replaced
  std::array<FaceTextureReport, 6> faces;
  bool fullFaces = false;  // whether `faces` were scored on whole faces or on the crops
  double lossBefore = 0, lossAfterCoarse = 0, lossAfterSearch = 0, lossAfter = 0;  // on the crops
  bool coarseSearched = false;                  // whether the coarse grid ran (options.coarseSearch)
  std::array<float, 3> coarseFactors{1, 1, 1};  // its choice: fibres, pores, rays
  std::string colourStep = "colours kept";      // "colours refitted", "face tints matched"
  int evaluations = 0, sweeps = 0, crops = 0;
  std::vector<double> sweepLosses;    // the loss after each sweep of the search
  std::vector<int> sweepEvaluations;  // and the evaluations of each
  // Points of the crops (shading_layers.hpp): composed into colours, and computed per layer group (rings,
  // latewood, pores, rays, fibres); load-independent measures of the search's cost.
  std::uint64_t composedPoints = 0;
  std::array<std::uint64_t, 5> layerPoints{};
  double coarseSeconds = 0, searchSeconds = 0, colourSeconds = 0, reportSeconds = 0, seconds = 0;
};

// photos: A..F (empty: no photo); at least one besides the held-out faces. Throws InputError (no photo, a
// photo whose proportions differ from its face, an unknown parameter id), Cancelled on request.
TextureInferenceResult inferTexture(const Block& block, const WoodParameters& params,
                                    const GrowthRates& rates, const std::array<Image, 6>& photos,
                                    const TextureInferenceOptions& options = {},
                                    const Progress& progress = {});

// The result as log lines: per-face orientation and distances before/after, losses, timings.
std::vector<std::string> formatTextureInferenceReport(const TextureInferenceResult& result);

}  // namespace kerf
