#pragma once
// A texture inference short enough for the editor tests (a second or so on the demo block), still a real
// background job with live previews: one small crop per face, no coarse search, two sweeps over four
// parameters.
#include "texture/texture_inference.hpp"

namespace kerf::testing {

inline TextureInferenceOptions quickTextureOptions() {
  TextureInferenceOptions options;
  options.loss.cropsPerFace = 1;
  options.loss.cropSize = 48;
  options.coarseSearch = false;
  options.search.maxSweeps = 2;
  options.parameters = {"pores.radius_earlywood", "pores.cell_size", "rays.spacing", "fibers.strength"};
  options.fullFaceReport = false;
  return options;
}

}  // namespace kerf::testing
