#pragma once
// The synthetic block of the texture-inference tests: the demo wood (demoProject) with rays made clearly
// visible (the demo's rays have nearly the earlywood's colour and are faint even to the eye), its six
// faces rendered as "photos" at 512 px (12.8 px/mm, as `kerf-cli demo` writes them) with another random
// seed than the candidates use: the same wood, other pores and rays, so only statistics can agree.
#include <array>
#include <glm/common.hpp>

#include "demo/demo_block.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"

namespace kerf::test {

struct TextureSynthetic {
  Project truth = demoProject(7);
  GrowthRates rates;
  std::array<Image, 6> photos;
  TextureSynthetic() {
    // The seed also drives the grain's wobble, the ring-to-ring colour and the mottling; a fitted project
    // holds those fixed (they are part of its growth field and colours), so here they are off and the
    // seed moves only pores, rays and fibres.
    truth.params.distortionAmplitude = 0;
    truth.params.ringColorVariation = 0;
    truth.params.mottleStrength = 0;
    // Rays that show: lighter than the wood, and 0.15 mm thick (2 px here; the demo's 0.06 mm is under
    // a pixel, where their spacing was left to the layouts' noise, docs/texture.md).
    truth.params.rayOpacity = 0.85f;
    truth.params.rayWidth = 0.15f;
    truth.params.rayColor = glm::min(truth.params.earlywoodColor * 1.2f, glm::vec3(1.0f));
    rates = truth.effectiveRates();
    const WoodModel model(truth.block, truth.params, rates);
    for (FaceId face : kAllFaces) photos[faceIndex(face)] = renderFace(model, face, {512, 512}, 2);
  }
  // The true parameters with another seed: what the inference should find.
  WoodParameters sameWoodOtherSeed() const {
    WoodParameters p = truth.params;
    p.seed = 3;
    return p;
  }
};

inline const TextureSynthetic& textureSynthetic() {
  static const TextureSynthetic s;
  return s;
}

}  // namespace kerf::test
