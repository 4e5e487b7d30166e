#pragma once
// The texture step of `kerf-cli texture` and `kerf-cli reconstruct --texture`: the detail of the wood
// (pores, rays, fibres, the early-to-late transition) and the colours inferred from the face photos
// (inferTexture, texture/texture_inference.hpp; Mokume Sec. 5.3.1 / A.2.3), its report on stdout, and the
// result put into the project.
#include <array>

#include "command.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "texture/texture_inference.hpp"

namespace kerf::cli {

// Infers the texture of `project` (its growth field, held-out faces skipped) from `photos` and replaces
// its parameters with the result; the rates are fixed in the project. Returns the inference's result.
TextureInferenceResult inferProjectTexture(Project& project, const std::array<Image, 6>& photos,
                                           TextureInferenceOptions options, Context& context);

// --appearance photo (`texture`, `reconstruct`): checks that the photo-true appearance can be made (the
// project's photos, less its held-out faces, load and fit their faces; InputError otherwise), stores the
// choice in the project and says which photos it is made from.
void storePhotoAppearance(Project& project);

}  // namespace kerf::cli
