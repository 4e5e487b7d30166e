#include "texture_step.hpp"

#include <cstdio>

#include "appearance/photo_true_appearance.hpp"
#include "render/wood_model.hpp"

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

void storePhotoAppearance(Project& project) {
  const WoodModel model(project);
  const PhotoTrueAppearance appearance(model, loadAppearancePhotos(project), project.heldOutFaces);
  std::string faces;
  for (FaceId face : appearance.exemplarFaces()) faces += faceLetter(face);
  project.appearance = Appearance::Photo;
  std::printf(
      "appearance: photo-true, made from the photos of faces %s at %.3g px/mm%s\n", faces.c_str(),
      appearance.synthesisPxPerMm(),
      project.heldOutFaces.empty() ? "" : (" (held out: " + project.heldOutFaces.letters() + ")").c_str());
}

}  // namespace kerf::cli
