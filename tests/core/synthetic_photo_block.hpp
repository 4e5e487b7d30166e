#pragma once
// A synthetic block with a known field, seen as a user's block is: its six faces rendered as photos by
// Kerf's own model (a species preset, wavy and eccentric rings, a tilted pith outside the block), the
// rings found by Kerf's own detector (rings/detect_block_rings.hpp), and the fit's input built from them
// as `kerf-cli fit` builds it. Shared by the uncertainty test and bench/calibrate_ring_uncertainty.
#include <array>
#include <glm/vec3.hpp>
#include <string>

#include "field/growth_rates.hpp"
#include "fit/growth_field_fit.hpp"
#include "image/gray_image.hpp"
#include "params/builtin_presets.hpp"
#include "params/presets.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "rings/detect_block_rings.hpp"

namespace kerf::testing {

struct SyntheticBlockSpec {
  std::string species = "kuri";
  int seed = 1;
  glm::vec3 pithOrigin{70, 0, -40};  // block mm: outside a 40 mm block, as most cut blocks' piths
  float tiltDeg = 4, azimuthDeg = 30;
  float pxPerMm = 6;  // a 40 mm face: 240 px (Mokume's photos: 256)
};

struct SyntheticPhotoBlock {
  Block block;
  WoodParameters truth;
  GrowthRates truthRates;
  GrowthFieldFitInput input;  // the rendered photos and the rings detected on them
  WoodParameters fitStart;    // the species' wood, the block's pith unknown (defaults)
  GrowthFieldFitOptions options;

  explicit SyntheticPhotoBlock(const SyntheticBlockSpec& spec) {
    const Preset* preset = builtInPreset(spec.species);
    if (!preset) throw InputError("no preset " + spec.species);
    fitStart = preset->parametersOnDefaults();
    truth = fitStart;
    truth.seed = spec.seed;
    truth.pithOrigin = spec.pithOrigin;
    truth.pithTilt = spec.tiltDeg;
    truth.pithAzimuth = spec.azimuthDeg;
    truth.eccentricity = 0.15f;
    truth.irregularity = 0.35f;
    truth.waviness = 0.15f;
    truthRates = synthesizeGrowthRates(truth, block);
    const WoodModel model(block, truth, truthRates);
    const std::array<Image, 6> photos = renderFaces(model, spec.pxPerMm, 2);
    const BlockRingDetection detection = detectBlockRings(photos, block);
    for (int i = 0; i < 6; ++i) {
      input.photos[i] = photos[i];
      if (detection.faces[i]) input.rings[i] = toGray8(detection.faces[i]->arl);
    }
    options.minContours = kMinFitContours;
    options.minFaces = kMinFitFaces;
  }
};

}  // namespace kerf::testing
