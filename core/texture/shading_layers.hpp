#pragma once
// The crops of many candidates of the texture search rendered at once, sharing what they agree on
// (issue 16 item 6, docs/performance.md). A point's colour is composed from layers (kernels/wood.glsl,
// WoodLayers), each set by its own group of parameters: the rings (profile, ring noise, mottling), the
// latewood share, the pores, the rays and the fibres. The compass search's trials change one coordinate
// each, so most of them agree on all but one group; a group's layer is computed once per distinct value of
// its parameters and crop, and only the composition (colours, pore darkness, ray and fibre strength) per
// candidate. The pixels are those of renderFaceCrop, bit for bit (core.ShadingLayers.*).
#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "io/image.hpp"
#include "texture/face_crops.hpp"
#include "util/progress.hpp"

namespace kerf {

class WoodModel;

// What was computed: points composed, and points of each layer group computed (rings, latewood, pores,
// rays, fibres), for the --stats report (load-independent counts).
struct ShadingCounts {
  std::atomic<std::uint64_t> composed{0};
  std::array<std::atomic<std::uint64_t>, 5> layers{};
};

// Every candidate's crops, rendered[c * crops.size() + k], `samples` x `samples` points per pixel, from the
// crops' stored locations (locateFaceCrop; every model must locate its points there). Parallel over layer
// items and then over (candidate, crop); cancellable.
std::vector<Image> renderCandidateCrops(const std::vector<const WoodModel*>& models,
                                        const std::vector<FaceCrop>& crops,
                                        const std::vector<std::vector<WoodLocation>>& locations, int samples,
                                        ShadingCounts* counts = nullptr, const Progress& progress = {});

}  // namespace kerf
