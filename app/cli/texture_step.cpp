#include "texture_step.hpp"

#include <cstdio>

namespace kerf::cli {

TextureInferenceResult inferProjectTexture(Project& project, const std::array<Image, 6>& photos,
                                           TextureInferenceOptions options, Context& context) {
  options.heldOut = project.heldOutFaces;
  const GrowthRates rates = project.effectiveRates();
  TextureInferenceResult result =
      inferTexture(project.block, project.params, rates, photos, options, context.progress());
  for (const std::string& line : formatTextureInferenceReport(result)) std::printf("%s\n", line.c_str());
  context.samples += static_cast<std::size_t>(result.evaluations) * result.crops * options.loss.cropSize *
                     options.loss.cropSize * options.loss.samples * options.loss.samples;
  project.params = result.params;
  if (!project.rates) project.rates = rates;
  return result;
}

}  // namespace kerf::cli
